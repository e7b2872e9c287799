#include "ExportSize.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace vct::ui {

QStringList ExportSize::presets(QSize view)
{
    const auto tr = [](const char* text) { return QCoreApplication::translate("ExportSize", text); };
    const auto entry = [](int w, int h, const QString& label) {
        return QStringLiteral("%1×%2 (%3)").arg(w).arg(h).arg(label);
    };
    return { entry(view.width(), view.height(), tr("the view")), entry(1280, 720, tr("HD")),
        entry(1920, 1080, tr("Full HD")), entry(2560, 1440, tr("QHD")), entry(3840, 2160, tr("4K UHD")),
        entry(1024, 1024, tr("square")) };
}

std::optional<QSize> ExportSize::parse(const QString& text)
{
    static const QRegularExpression kSize(QStringLiteral("^\\s*(\\d{1,6})\\s*[x×X*]\\s*(\\d{1,6})"));
    const QRegularExpressionMatch match = kSize.match(text);
    if (!match.hasMatch())
        return std::nullopt;
    const int w = match.captured(1).toInt(), h = match.captured(2).toInt();
    if (w < 1 || h < 1 || w > kMaxSide || h > kMaxSide)
        return std::nullopt;
    return QSize(w, h);
}

} // namespace vct::ui
