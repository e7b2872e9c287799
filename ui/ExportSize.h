#pragma once

#include <QSize>
#include <QString>
#include <QStringList>

#include <optional>

namespace vct::ui {

/** The image sizes File > Export image offers, and reading one typed as "1920x1080" or "1920×1080". */
class ExportSize {
public:
    static constexpr int kMaxSide = 16384; ///< as vct-render's --width and --height

    /** The view's own size first (`view`, device pixels), then common sizes; each as "W×H" with a label. */
    static QStringList presets(QSize view);
    /** The size at the start of `text` ("1920×1080 (Full HD)", "800 x 600"); nothing when there is none or a
     * side is outside 1..kMaxSide. */
    static std::optional<QSize> parse(const QString& text);
};

} // namespace vct::ui
