#include "MixedSpinBox.h"

#include <QSignalBlocker>

#include <algorithm>
#include <cmath>

namespace vct::ui {

MixedSpinBox::MixedSpinBox(QWidget* parent)
    : QDoubleSpinBox(parent)
{
    setSpecialValueText(tr("mixed"));
}

void MixedSpinBox::showMixed()
{
    const QSignalBlocker block(this);
    setValue(minimum());
}

double MixedSpinBox::smallestValue() const
{
    return minimum() + std::pow(10.0, -decimals());
}

void MixedSpinBox::stepBy(int steps)
{
    if (isMixed())
        return;
    // Stepped silently first, so that a step past the smallest value never announces the marker: listeners
    // see one change, to where the step ends.
    const double before = value();
    {
        const QSignalBlocker block(this);
        QDoubleSpinBox::stepBy(steps);
    }
    const double after = std::max(value(), smallestValue());
    {
        const QSignalBlocker block(this);
        setValue(before);
    }
    setValue(after);
}

QAbstractSpinBox::StepEnabled MixedSpinBox::stepEnabled() const
{
    if (isMixed())
        return StepNone;
    StepEnabled enabled = QDoubleSpinBox::stepEnabled();
    if (value() <= smallestValue())
        enabled &= ~StepDownEnabled;
    return enabled;
}

} // namespace vct::ui
