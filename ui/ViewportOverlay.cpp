#include "ViewportOverlay.h"

#include "ViewProjection.h"

#include "document/Document.h"

#include <glm/geometric.hpp>

#include <QPainter>

#include <algorithm>
#include <array>
#include <cmath>

namespace vct::ui {

namespace {

const QColor kSelection(255, 150, 40);
const QColor kLight(255, 230, 90);

/** The rim of a surface light, from the triangles it is drawn with: a rect's four corners, a disk's polygon.
 */
std::vector<glm::vec3> rimOf(const render::SurfaceLight& light)
{
    const std::vector<glm::vec3> triangles = light.triangles();
    std::vector<glm::vec3> rim;
    if (light.shape == render::SurfaceLight::Shape::Rectangle) {
        if (triangles.size() == 6)
            rim = { triangles[0], triangles[1], triangles[2], triangles[5] };
    } else {
        for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
            rim.push_back(triangles[t + 1]); // a fan about the centre: each triangle's first rim corner
    }
    return rim;
}

QString mebibytes(std::size_t bytes)
{
    return QStringLiteral("%1 MiB").arg(double(bytes) / double(1 << 20), 0, 'f', 0);
}

} // namespace

ViewportOverlay::ViewportOverlay(QWidget* parent, const doc::Document* document)
    : QWidget(parent)
    , m_document(document)
{
    setObjectName(QStringLiteral("viewportOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setFocusPolicy(Qt::NoFocus);
}

void ViewportOverlay::setBusy(const QString& text)
{
    m_busy = text;
    update();
}

void ViewportOverlay::showFrame(const render::FrameStats& stats, bool interactive, const QRect& image)
{
    m_image = image;
    m_busy.clear();
    QStringList busy;
    for (const render::PassStats& pass : stats.passes)
        if (pass.name == "voxelize" && pass.action == "run")
            busy << tr("re-voxelizing");
    // A staged rebuild shows the last complete image until its remaining passes have run.
    const auto deferred = std::find_if(stats.passes.begin(), stats.passes.end(),
        [](const render::PassStats& pass) { return pass.action == "deferred"; });
    if (deferred != stats.passes.end())
        busy << tr("rebuilding: %1 next").arg(QString::fromStdString(deferred->name));
    if (!stats.lightConverged)
        busy << tr("converging bounces: iteration %1, change %2%")
                    .arg(stats.bounceIterations)
                    .arg(100.0 * stats.bounceResidual, 0, 'f', 1);
    if (interactive)
        busy << tr("preview while moving");
    QStringList lines;
    lines << tr("%1×%2 · %3 ms GPU")
                 .arg(stats.width)
                 .arg(stats.height)
                 .arg(stats.totalGpuMs, 0, 'f', stats.totalGpuMs < 10.0 ? 1 : 0);
    // "%1³" would read as placeholder 13: the cube goes on after the number.
    lines << tr("voxels %1").arg(stats.voxelResolution) + QStringLiteral("³ · ")
            + mebibytes(stats.voxelBytes);
    lines << (busy.isEmpty() ? tr("up to date") : busy.join(QStringLiteral(" · ")));
    m_status = lines.join(QLatin1Char('\n'));
    update();
}

std::optional<QPointF> ViewportOverlay::project(const glm::vec3& world) const
{
    if (!m_document)
        return std::nullopt;
    return ViewProjection { m_document->state().camera, QRectF(m_image) }.toScreen(world);
}

std::vector<std::pair<int, QPointF>> ViewportOverlay::lightIcons() const
{
    std::vector<std::pair<int, QPointF>> icons;
    if (!m_document)
        return icons;
    const std::vector<doc::LightNode>& lights = m_document->state().lights;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].type != doc::LightType::Directional)
            if (const std::optional<QPointF> p = project(lights[i].position))
                icons.emplace_back(int(i), *p);
    return icons;
}

QList<QPointF> ViewportOverlay::lightIconPositions() const
{
    QList<QPointF> positions;
    for (const auto& [light, position] : lightIcons())
        positions << position;
    return positions;
}

int ViewportOverlay::lightAt(const QPointF& point, double radius) const
{
    int nearest = -1;
    double best = radius;
    for (const auto& [light, position] : lightIcons())
        if (const double distance = std::hypot(position.x() - point.x(), position.y() - point.y());
            distance <= best) {
            best = distance;
            nearest = light;
        }
    return nearest;
}

QList<QPolygonF> ViewportOverlay::surfaceLightOutlines() const
{
    QList<QPolygonF> outlines;
    if (!m_document)
        return outlines;
    for (const doc::LightNode& light : m_document->state().lights) {
        if (!light.isSurface())
            continue;
        QPolygonF outline;
        for (const glm::vec3& corner : rimOf(light.surfaceLight())) {
            const std::optional<QPointF> p = project(corner);
            if (!p) {
                outline.clear();
                break;
            }
            outline << *p;
        }
        if (outline.size() >= 3)
            outlines << outline;
    }
    return outlines;
}

QList<QLineF> ViewportOverlay::selectionEdges() const
{
    QList<QLineF> edges;
    if (!m_document)
        return edges;
    const render::Aabb box = m_document->nodeWorldBounds(m_document->selectedNode());
    if (box.isEmpty())
        return edges;
    std::array<std::optional<QPointF>, 8> corners;
    for (int i = 0; i < 8; ++i)
        corners[std::size_t(i)] = project({ (i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
            (i & 4) ? box.max.z : box.min.z });
    for (int i = 0; i < 8; ++i)
        for (int bit : { 1, 2, 4 })
            if (!(i & bit) && corners[std::size_t(i)] && corners[std::size_t(i | bit)])
                edges << QLineF(*corners[std::size_t(i)], *corners[std::size_t(i | bit)]);
    return edges;
}

void ViewportOverlay::setGizmo(const TransformGizmo& gizmo, int highlighted)
{
    m_gizmo = gizmo;
    m_gizmoHighlight = highlighted;
    update();
}

void ViewportOverlay::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setClipRect(m_image);

    painter.setPen(QPen(kSelection, 1.5));
    for (const QLineF& edge : selectionEdges())
        painter.drawLine(edge);

    painter.setPen(QPen(kLight, 1.5));
    for (const QPolygonF& outline : surfaceLightOutlines())
        painter.drawPolygon(outline);
    painter.setBrush(kLight);
    for (const QPointF& p : lightIconPositions())
        painter.drawEllipse(p, 4.0, 4.0);
    painter.setBrush(Qt::NoBrush);
    // Spots show their axis; a sun, the way it shines, from the top right corner.
    if (m_document) {
        const render::Camera& camera = m_document->state().camera;
        const float reach = 0.05f * glm::length(camera.lookAt - camera.position);
        for (const doc::LightNode& light : m_document->state().lights) {
            if (light.type == doc::LightType::Spot && glm::length(light.direction) > 0.0f) {
                const auto from = project(light.position);
                const auto to = project(light.position + reach * glm::normalize(light.direction));
                if (from && to)
                    painter.drawLine(*from, *to);
            } else if (light.type == doc::LightType::Directional && glm::length(light.direction) > 0.0f) {
                const auto from = project(camera.lookAt);
                const auto to = project(camera.lookAt + reach * glm::normalize(light.direction));
                if (!from || !to)
                    continue;
                QPointF along = *to - *from;
                const double length = std::hypot(along.x(), along.y());
                const QPointF centre(m_image.right() - 28.0, m_image.top() + 28.0);
                painter.drawEllipse(centre, 7.0, 7.0);
                if (length > 1e-6) {
                    along *= 18.0 / length;
                    painter.drawLine(centre, centre + along);
                }
            }
        }
    }

    // The gizmo on top of the icons, each handle outlined in black so it reads on any image.
    for (const TransformGizmo::Handle& handle : m_gizmo.handles()) {
        const bool lit = handle.part == m_gizmoHighlight;
        const QColor colour = lit ? handle.colour.lighter(140) : handle.colour;
        for (const auto& [pen, width] :
            { std::pair { QColor(0, 0, 0, 160), lit ? 5.0 : 4.0 }, std::pair { colour, lit ? 3.0 : 2.0 } }) {
            painter.setPen(QPen(pen, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            if (handle.closed)
                painter.drawPolygon(handle.shape);
            else
                painter.drawPolyline(handle.shape);
        }
    }

    if (!m_busy.isEmpty()) {
        const QRectF box
            = painter.boundingRect(QRectF(m_image), Qt::AlignCenter, m_busy).adjusted(-12, -8, 12, 8);
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(0, 0, 0, 170));
        painter.drawRoundedRect(box, 4, 4);
        painter.setPen(Qt::white);
        painter.drawText(box, Qt::AlignCenter, m_busy);
    }
    if (m_status.isEmpty())
        return;
    const QRectF text = painter.boundingRect(QRectF(m_image.left() + 8, m_image.bottom() - 200, 400, 192),
        Qt::AlignLeft | Qt::AlignBottom, m_status);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 140));
    painter.drawRoundedRect(text.adjusted(-4, -3, 4, 3), 3, 3);
    painter.setPen(Qt::white);
    painter.drawText(text, Qt::AlignLeft | Qt::AlignBottom, m_status);
}

} // namespace vct::ui
