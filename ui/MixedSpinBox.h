#pragma once

#include <QDoubleSpinBox>

namespace vct::ui {

/**
 * A spin box for one field that stands for several values which may differ, like a uniform scale over three
 * axes. Its minimum is no value but a marker shown as "mixed". Typing any number replaces the marker and
 * always changes the value, so it is always an edit; stepping never starts from the marker (a wheel turn over
 * "mixed" would otherwise jump to the smallest value) and never lands on it.
 */
class MixedSpinBox : public QDoubleSpinBox {
    Q_OBJECT

public:
    explicit MixedSpinBox(QWidget* parent = nullptr);

    bool isMixed() const { return value() <= minimum(); }
    /** Shows "mixed" without emitting valueChanged. */
    void showMixed();
    /** The smallest value that is not the marker: one unit of the last decimal above the minimum. */
    double smallestValue() const;

    void stepBy(int steps) override;

protected:
    StepEnabled stepEnabled() const override;
};

} // namespace vct::ui
