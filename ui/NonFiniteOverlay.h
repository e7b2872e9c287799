#pragma once

#include "core/NonFiniteCount.h"

#include <QLabel>

#include <cstdint>
#include <vector>

namespace vct::ui {

/**
 * The viewport's NaN/Inf check, drawn over the image: the total of non-finite texels found by the
 * renderer's reduction pass over every render target and voxel mip level, and which resources hold them.
 * A NaN filtered away by a later pass never reaches the screen's magenta, so the per-resource list is what
 * tells where one was born.
 */
class NonFiniteOverlay : public QLabel {
    Q_OBJECT

public:
    explicit NonFiniteOverlay(QWidget* parent);

    void showCounts(const std::vector<render::NonFiniteCount>& counts);
    std::uint64_t total() const { return m_total; }
    int checkedResources() const { return m_checked; }

private:
    std::uint64_t m_total = 0;
    int m_checked = 0;
};

} // namespace vct::ui
