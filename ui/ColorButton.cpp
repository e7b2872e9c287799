#include "ColorButton.h"

#include <QColorDialog>
#include <QPainter>
#include <QPixmap>

#include <algorithm>
#include <cmath>

namespace vct::ui {

namespace {

// QColorDialog and the screen work in sRGB; the document stores linear values. Converting keeps the swatch
// looking like the rendered surface (as Blender's colour picker does) while the label shows the stored
// numbers.
float linearToSrgb(float v)
{
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float v)
{
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

QColor toQColor(const glm::vec3& linear)
{
    return QColor::fromRgbF(linearToSrgb(linear.x), linearToSrgb(linear.y), linearToSrgb(linear.z));
}

glm::vec3 fromQColor(const QColor& c)
{
    return { srgbToLinear(float(c.redF())), srgbToLinear(float(c.greenF())), srgbToLinear(float(c.blueF())) };
}

} // namespace

ColorButton::ColorButton(QWidget* parent)
    : QToolButton(parent)
{
    setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setIconSize(QSize(28, 14));
    connect(this, &QToolButton::clicked, this, &ColorButton::openDialog);
    refresh();
}

void ColorButton::setColor(const glm::vec3& linear)
{
    if (linear == m_color)
        return;
    m_color = linear;
    refresh();
}

void ColorButton::pick(const glm::vec3& linear)
{
    if (linear == m_color)
        return;
    m_color = linear;
    refresh();
    emit colorChanged(m_color);
}

void ColorButton::openDialog()
{
    const glm::vec3 original = m_color;
    auto* dialog = new QColorDialog(toQColor(m_color), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(m_dialogTitle.isEmpty() ? tr("Colour") : m_dialogTitle);
    connect(
        dialog, &QColorDialog::currentColorChanged, this, [this](const QColor& c) { pick(fromQColor(c)); });
    connect(dialog, &QColorDialog::colorSelected, this, [this](const QColor& c) { pick(fromQColor(c)); });
    connect(dialog, &QDialog::rejected, this, [this, original] { pick(original); });
    connect(dialog, &QDialog::finished, this, &ColorButton::editingFinished);
    dialog->open();
}

void ColorButton::refresh()
{
    QPixmap swatch(iconSize());
    swatch.fill(toQColor(m_color));
    QPainter painter(&swatch);
    painter.setPen(palette().color(QPalette::Mid));
    painter.drawRect(swatch.rect().adjusted(0, 0, -1, -1));
    painter.end();
    setIcon(QIcon(swatch));
    setText(QStringLiteral("%1  %2  %3")
                .arg(double(m_color.x), 0, 'f', 3)
                .arg(double(m_color.y), 0, 'f', 3)
                .arg(double(m_color.z), 0, 'f', 3));
    setToolTip(tr("Linear RGB %1. Click to pick; the picker shows sRGB.").arg(text()));
}

} // namespace vct::ui
