#include "TestSupport.h"

#include "Document.h"
#include "SceneLoader.h"

#include <QDir>
#include <QFile>
// Qt Gui comes with vct_document (QUndoStack); the test paints its textures with QImage.
#include <QSignalSpy>
#include <QtGui/QImage>
#include <QtTest>

#include <functional>

using vct::doc::ChangeEvent;
using vct::doc::Document;
using vct::doc::DocumentState;
using vct::doc::LightField;
using vct::doc::LightNode;
using vct::doc::LightType;
using vct::doc::MaterialField;
using vct::doc::NodeTransform;
using vct::doc::NodeTransformField;
using vct::doc::sameDocument;
using vct::doc::sameMaterial;

namespace {

/** Records every `changed` event of a document. */
class EventLog {
public:
    explicit EventLog(Document& document)
    {
        QObject::connect(
            &document, &Document::changed, &m_context, [this](const ChangeEvent& e) { events.push_back(e); });
    }
    bool contains(ChangeEvent::Kind kind, int index) const
    {
        return std::any_of(events.begin(), events.end(),
            [&](const ChangeEvent& e) { return e.kind == kind && e.index == index; });
    }
    std::vector<ChangeEvent> events;

private:
    QObject m_context;
};

/** A one-triangle OBJ with its own red material, written into the test output folder. */
QString writeTriangleObj(const QString& folder, const QString& name)
{
    QDir().mkpath(folder);
    const QString stem = QDir(folder).filePath(name);
    QFile mtl(stem + QStringLiteral(".mtl"));
    if (!mtl.open(QIODevice::WriteOnly))
        return {};
    mtl.write("newmtl imported_red\nKd 0.9 0.1 0.1\n");
    mtl.close();
    QFile obj(stem + QStringLiteral(".obj"));
    if (!obj.open(QIODevice::WriteOnly))
        return {};
    obj.write(QStringLiteral(
        "mtllib %1.mtl\no Wedge\nv 0 0 0\nv 0.5 0 0\nv 0 0.5 0\nusemtl imported_red\nf 1 2 3\n")
                  .arg(name)
                  .toUtf8());
    obj.close();
    return obj.fileName();
}

/** A textured quad whose texture is one solid colour, for checking which texture a material ends up with. */
QString writeTexturedObj(const QString& folder, const QString& name, QColor color)
{
    QDir().mkpath(folder);
    const QString stem = QDir(folder).filePath(name);
    QImage image(4, 4, QImage::Format_RGBA8888);
    image.fill(color);
    if (!image.save(stem + QStringLiteral(".png")))
        return {};
    QFile mtl(stem + QStringLiteral(".mtl"));
    if (!mtl.open(QIODevice::WriteOnly))
        return {};
    mtl.write(QStringLiteral("newmtl %1_mat\nKd 1 1 1\nmap_Kd %1.png\n").arg(name).toUtf8());
    mtl.close();
    QFile obj(stem + QStringLiteral(".obj"));
    if (!obj.open(QIODevice::WriteOnly))
        return {};
    obj.write(
        QStringLiteral("mtllib %1.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                       "vn 0 0 1\nusemtl %1_mat\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n")
            .arg(name)
            .toUtf8());
    obj.close();
    return obj.fileName();
}

} // namespace

class tst_Document : public QObject {
    Q_OBJECT

private:
    bool openCornell(Document& doc)
    {
        QString error;
        const bool ok = doc.newFromScene(QStringLiteral("builtin:cornell"), &error);
        if (!ok)
            qWarning() << error;
        return ok;
    }

private slots:
    void newFromSceneMirrorsTheLoadedScene()
    {
        Document doc;
        EventLog log(doc);
        QVERIFY(openCornell(doc));
        vct::render::Scene loaded;
        QString error;
        QVERIFY2(vct::doc::SceneLoader::load(QStringLiteral("builtin:cornell"), loaded, &error),
            qPrintable(error));

        const DocumentState& s = doc.state();
        QCOMPARE(s.materials.size(), std::size_t(5));
        QCOMPARE(s.sources.size(), std::size_t(1));
        QCOMPARE(s.sources[0].spec, QStringLiteral("builtin:cornell"));
        QCOMPARE(s.nodes.size(), loaded.meshes.size());
        QVERIFY(!s.nodes.empty());
        for (std::size_t i = 0; i < s.nodes.size(); ++i) {
            QCOMPARE(s.nodes[i].mesh, int(i));
            QCOMPARE(s.nodes[i].material, loaded.meshes[i].material);
            QVERIFY(!s.nodes[i].name.isEmpty());
            QVERIFY(s.nodes[i].id > 0 && s.nodes[i].id < s.nextId);
        }
        QCOMPARE(s.camera.position, loaded.camera.position);
        QCOMPARE(s.camera.fovYDeg, loaded.camera.fovYDeg);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(!doc.isModified());
        QVERIFY(doc.filePath().isEmpty());
        QCOMPARE(doc.selectedNode(), -1);
        QVERIFY(log.contains(ChangeEvent::Kind::Reset, -1));

        std::vector<int> meshToNode;
        const vct::render::Scene built = doc.buildRenderScene(&meshToNode);
        QCOMPARE(built.triangleCount(), loaded.triangleCount());
        QCOMPARE(built.meshes.size(), loaded.meshes.size());
        QCOMPARE(meshToNode.size(), built.meshes.size());
        QCOMPARE(built.hasEmissiveMaterial(), loaded.hasEmissiveMaterial());
        QCOMPARE(built.materials.size(), loaded.materials.size());
    }

    void lightsBecomeColourTimesIntensity()
    {
        Document doc;
        QString error;
        QVERIFY2(doc.newFromScene(QStringLiteral("builtin:cornell_point"), &error), qPrintable(error));
        vct::render::Scene loaded;
        QVERIFY(vct::doc::SceneLoader::load(QStringLiteral("builtin:cornell_point"), loaded, &error));
        QCOMPARE(doc.state().lights.size(), loaded.pointLights.size() + loaded.directionalLights.size());
        QVERIFY(!doc.state().lights.empty());
        const LightNode& light = doc.state().lights.front();
        QCOMPARE(light.name, QStringLiteral("Point light 1"));
        QCOMPARE(std::max({ light.color.x, light.color.y, light.color.z }), 1.0f);
        const vct::render::Scene built = doc.buildRenderScene();
        QCOMPARE(built.pointLights.size(), loaded.pointLights.size());
        for (int c = 0; c < 3; ++c)
            QVERIFY(std::abs(built.pointLights[0].intensity[c] - loaded.pointLights[0].intensity[c])
                <= 1e-5f * loaded.pointLights[0].intensity[c]);
    }

    void everyEditPushesOneUndoableCommand_data()
    {
        QTest::addColumn<int>("edit");
        const char* names[] = { "transform", "name", "visible", "dynamic", "duplicate", "delete", "material",
            "light", "addLight", "removeLight", "settings" };
        for (int i = 0; i < int(std::size(names)); ++i)
            QTest::newRow(names[i]) << i;
    }

    void everyEditPushesOneUndoableCommand()
    {
        QFETCH(int, edit);
        Document doc;
        QVERIFY(openCornell(doc));
        LightNode light;
        light.name = QStringLiteral("Extra");
        light.position = { 0.1f, 0.5f, 0.2f };
        light.intensity = 3.0f;
        doc.addLight(light); // so that there is a light to edit and remove
        doc.undoStack()->clear();

        const std::vector<std::function<void()>> edits = {
            [&] {
                doc.setNodeTransform(
                    1, { { 0.1f, 0.2f, 0.3f }, { 0.0f, 45.0f, 0.0f }, { 1.0f, 2.0f, 1.0f } });
            },
            [&] { doc.setNodeName(1, QStringLiteral("Renamed")); },
            [&] { doc.setNodeVisible(1, false); },
            [&] { doc.setNodeDynamic(1, true); },
            [&] { doc.duplicateNode(1); },
            [&] { doc.deleteNode(1); },
            [&] {
                auto m = doc.state().materials[2];
                m.albedo = { 0.2f, 0.3f, 0.4f };
                m.shininess = 50.0f;
                m.specular = glm::vec3(0.1f);
                doc.setMaterial(2, m);
            },
            [&] {
                LightNode l = doc.state().lights.back();
                l.intensity = 7.0f;
                l.color = { 1.0f, 0.5f, 0.25f };
                doc.setLight(int(doc.state().lights.size()) - 1, l);
            },
            [&] { doc.addLight(light); },
            [&] { doc.removeLight(0); },
            [&] {
                auto settings = doc.state().settings;
                QVERIFY(settings.set("voxel_res", "64").empty());
                doc.setSettings(settings);
            },
        };

        const DocumentState before = doc.state();
        edits[std::size_t(edit)]();
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(doc.isModified());
        QVERIFY(!doc.undoStack()->text(0).isEmpty());
        const DocumentState after = doc.state();
        QVERIFY(!sameDocument(before, after));

        doc.undoStack()->undo();
        QVERIFY(sameDocument(before, doc.state()));
        QVERIFY(!doc.isModified());
        doc.undoStack()->redo();
        QVERIFY(sameDocument(after, doc.state()));

        // The same value again is no edit for the property setters.
        if (edit <= 3 || edit == 6 || edit == 7 || edit == 10) {
            edits[std::size_t(edit)]();
            QCOMPARE(doc.undoStack()->count(), 1);
            QCOMPARE(doc.undoStack()->index(), 1);
        }
    }

    void noOpEditsPushNothing()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        const DocumentState& s = doc.state();
        doc.setNodeTransform(0, s.nodes[0].transform);
        doc.setNodeName(0, s.nodes[0].name);
        doc.setNodeVisible(0, true);
        doc.setNodeDynamic(0, s.nodes[0].dynamic);
        doc.setMaterial(0, s.materials[0]);
        doc.setSettings(s.settings);
        doc.setNodeTransform(999, {});
        doc.deleteNode(-1);
        doc.removeLight(12345);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(!doc.isModified());
    }

    void transformDragsMergePerNode()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        const DocumentState before = doc.state();
        for (int step = 1; step <= 5; ++step)
            doc.setNodeTransform(0, { { 0.0f, 0.1f * float(step), 0.0f }, glm::vec3(0.0f), glm::vec3(1.0f) });
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.state().nodes[0].transform.translation.y, 0.5f);
        QVERIFY(doc.undoStack()->text(0).startsWith(QStringLiteral("Move ")));

        doc.setNodeTransform(1, { { 1.0f, 0.0f, 0.0f }, glm::vec3(0.0f), glm::vec3(1.0f) });
        doc.setNodeTransform(1, { { 2.0f, 0.0f, 0.0f }, glm::vec3(0.0f), glm::vec3(1.0f) });
        QCOMPARE(doc.undoStack()->count(), 2);
        doc.setNodeTransform(0, { { 0.0f, 0.7f, 0.0f }, glm::vec3(0.0f), glm::vec3(1.0f) });
        QCOMPARE(doc.undoStack()->count(), 3);

        doc.undoStack()->undo();
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(sameDocument(before, doc.state()));

        // A drag back to where it started leaves nothing to undo.
        doc.undoStack()->clear();
        doc.setNodeTransform(0, { { 0.0f, 0.3f, 0.0f }, glm::vec3(0.0f), glm::vec3(1.0f) });
        doc.setNodeTransform(0, before.nodes[0].transform);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(sameDocument(before, doc.state()));
    }

    void transformFieldsAreSeparateSteps()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        const NodeTransform before = doc.state().nodes[0].transform;
        NodeTransform t = before;
        // Two edits of X (typing "1", then "12"), then Y, then X again: three steps.
        for (float x : { 1.0f, 12.0f }) {
            t.translation.x = x;
            doc.setNodeTransform(0, t, NodeTransformField::TranslationX);
        }
        QCOMPARE(doc.undoStack()->count(), 1);
        t.translation.y = 2.0f;
        doc.setNodeTransform(0, t, NodeTransformField::TranslationY);
        t.translation.x = 3.0f;
        doc.setNodeTransform(0, t, NodeTransformField::TranslationX);
        QCOMPARE(doc.undoStack()->count(), 3);
        // A viewport drag after a panel edit is a step of its own too.
        t.translation.z = 4.0f;
        doc.setNodeTransform(0, t);
        QCOMPARE(doc.undoStack()->count(), 4);
        t.rotationDeg.y = 30.0f;
        doc.setNodeTransform(0, t, NodeTransformField::RotationY);
        t.scale = glm::vec3(2.0f);
        doc.setNodeTransform(0, t, NodeTransformField::UniformScale);
        QCOMPARE(doc.undoStack()->count(), 6);
        QVERIFY(doc.undoStack()->text(4).startsWith(QStringLiteral("Rotate ")));
        QVERIFY(doc.undoStack()->text(5).startsWith(QStringLiteral("Scale ")));

        doc.undoStack()->undo();
        QCOMPARE(doc.state().nodes[0].transform.scale, before.scale);
        QCOMPARE(doc.state().nodes[0].transform.rotationDeg.y, 30.0f);
        doc.undoStack()->setIndex(2);
        QCOMPARE(doc.state().nodes[0].transform.translation, glm::vec3(12.0f, 2.0f, before.translation.z));
        doc.undoStack()->setIndex(0);
        QVERIFY(doc.state().nodes[0].transform == before);
    }

    void materialEditsMerge()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        const DocumentState before = doc.state();
        EventLog log(doc);
        for (int step = 1; step <= 4; ++step) {
            auto m = doc.state().materials[1];
            m.albedo.x = 0.1f * float(step);
            doc.setMaterial(1, m);
        }
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(doc.undoStack()->text(0).startsWith(QStringLiteral("Edit material ")));
        QVERIFY(log.contains(ChangeEvent::Kind::Material, 1));
        auto other = doc.state().materials[2];
        other.shininess = 10.0f;
        other.specular = glm::vec3(0.2f);
        doc.setMaterial(2, other);
        QCOMPARE(doc.undoStack()->count(), 2);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(sameDocument(before, doc.state()));
    }

    void lightAndSettingsEditsMerge()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        doc.addLight(LightNode {});
        QCOMPARE(doc.state().lights.back().name, QStringLiteral("Point light 1"));
        const int index = int(doc.state().lights.size()) - 1;
        for (int step = 1; step <= 3; ++step) {
            LightNode l = doc.state().lights[std::size_t(index)];
            l.intensity = float(step);
            doc.setLight(index, l);
        }
        QCOMPARE(doc.undoStack()->count(), 2);

        for (float exposure : { 1.5f, 2.0f, 2.5f }) {
            auto settings = doc.state().settings;
            settings.exposure = exposure;
            doc.setSettings(settings);
        }
        QCOMPARE(doc.undoStack()->count(), 3);
        auto settings = doc.state().settings;
        settings.voxelResolution = 64;
        doc.setSettings(settings);
        QCOMPARE(doc.undoStack()->count(), 4);
    }

    void materialFieldsAreSeparateSteps()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        QUndoStack* undo = doc.undoStack();
        const vct::render::Material before = doc.state().materials[1];
        const QString name = QString::fromStdString(before.name);
        const auto material = [&] { return doc.state().materials[1]; };
        vct::render::Material m = before;

        // Albedo twice in one gesture (a colour dialog's live preview): one step.
        for (float red : { 0.3f, 0.4f }) {
            m.albedo.x = red;
            doc.setMaterial(1, m, MaterialField::Albedo);
        }
        QCOMPARE(undo->count(), 1);
        QCOMPARE(undo->text(0), QStringLiteral("Albedo of %1").arg(name));
        // Then the shininess, twice: the next step, one for both.
        m.specular = glm::vec3(0.1f);
        doc.setMaterial(1, m, MaterialField::Specular);
        for (float shininess : { 5.0f, 50.0f }) {
            m.shininess = shininess;
            doc.setMaterial(1, m, MaterialField::Shininess);
        }
        QCOMPARE(undo->count(), 3);
        QCOMPARE(undo->text(1), QStringLiteral("Specular of %1").arg(name));
        QCOMPARE(undo->text(2), QStringLiteral("Shininess of %1").arg(name));
        // Emission colour and strength are two fields although both set the emission.
        m.emission = glm::vec3(1.0f, 0.5f, 0.5f);
        doc.setMaterial(1, m, MaterialField::EmissionColor);
        m.emission = glm::vec3(4.0f, 2.0f, 2.0f);
        doc.setMaterial(1, m, MaterialField::EmissionStrength);
        QCOMPARE(undo->count(), 5);
        QCOMPARE(undo->text(4), QStringLiteral("Emission strength of %1").arg(name));
        // The albedo again, after other fields: a step of its own, not merged into the first.
        m.albedo.y = 0.6f;
        doc.setMaterial(1, m, MaterialField::Albedo);
        QCOMPARE(undo->count(), 6);
        const vct::render::Material edited = material();

        // Each undo reverts exactly its own field.
        undo->undo();
        QCOMPARE(material().albedo, glm::vec3(0.4f, before.albedo.y, before.albedo.z));
        QCOMPARE(material().emission, glm::vec3(4.0f, 2.0f, 2.0f));
        undo->undo();
        QCOMPARE(material().emission, glm::vec3(1.0f, 0.5f, 0.5f));
        undo->undo();
        QCOMPARE(material().emission, before.emission);
        QCOMPARE(material().shininess, 50.0f);
        undo->undo();
        QCOMPARE(material().shininess, before.shininess);
        QCOMPARE(material().specular, glm::vec3(0.1f));
        undo->undo();
        QCOMPARE(material().specular, before.specular);
        QCOMPARE(material().albedo.x, 0.4f);
        undo->undo();
        QVERIFY(sameMaterial(material(), before));
        undo->setIndex(undo->count());
        QVERIFY(sameMaterial(material(), edited));
    }

    void materialMergesStopAtGesturesSwitchesAndUndo()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        QUndoStack* undo = doc.undoStack();
        const vct::render::Material before = doc.state().materials[1];
        vct::render::Material m = before;

        // Enter or a closed dialog ends the gesture: the same field again is a new step.
        m.shininess = 10.0f;
        doc.setMaterial(1, m, MaterialField::Shininess);
        doc.endEditGesture();
        m.shininess = 20.0f;
        doc.setMaterial(1, m, MaterialField::Shininess);
        QCOMPARE(undo->count(), 2);
        // The same field of another material is another step.
        vct::render::Material other = doc.state().materials[2];
        other.shininess = 30.0f;
        doc.setMaterial(2, other, MaterialField::Shininess);
        QCOMPARE(undo->count(), 3);
        // Each click of a switch is a step: merged, the second would cancel the first and leave nothing.
        m.doubleSided = !before.doubleSided;
        doc.setMaterial(1, m, MaterialField::DoubleSided);
        m.doubleSided = before.doubleSided;
        doc.setMaterial(1, m, MaterialField::DoubleSided);
        QCOMPARE(undo->count(), 5);
        QVERIFY(undo->text(4).startsWith(QStringLiteral("Double-sided switch of ")));

        // After an undo, an edit of the field below the undone step does not merge into that step.
        undo->setIndex(2); // shininess 20, the other material untouched
        m.shininess = 40.0f;
        doc.setMaterial(1, m, MaterialField::Shininess);
        QCOMPARE(undo->count(), 3);
        undo->undo();
        QCOMPARE(doc.state().materials[1].shininess, 20.0f);
        undo->undo();
        QCOMPARE(doc.state().materials[1].shininess, 10.0f);
        undo->undo();
        QVERIFY(sameMaterial(doc.state().materials[1], before));
    }

    void lightFieldsAreSeparateSteps()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        doc.addLight(LightNode {});
        doc.undoStack()->clear();
        QUndoStack* undo = doc.undoStack();
        const int index = int(doc.state().lights.size()) - 1;
        const LightNode before = doc.state().lights[std::size_t(index)];
        const auto light = [&] { return doc.state().lights[std::size_t(index)]; };
        LightNode l = before;

        // Intensity typed digit by digit ("2", "25"): one step; then X: the next.
        for (float intensity : { 2.0f, 25.0f }) {
            l.intensity = intensity;
            doc.setLight(index, l, LightField::Intensity);
        }
        QCOMPARE(undo->count(), 1);
        QCOMPARE(undo->text(0), QStringLiteral("Light intensity of Point light 1"));
        for (float x : { 0.5f, 0.75f }) {
            l.position.x = x;
            doc.setLight(index, l, LightField::PositionX);
        }
        QCOMPARE(undo->count(), 2);
        QCOMPARE(undo->text(1), QStringLiteral("Light position X of Point light 1"));
        // Another axis is another field.
        l.position.y = 2.0f;
        doc.setLight(index, l, LightField::PositionY);
        // The colour, and a spot angle that carries the other along: one step each.
        l.color = { 1.0f, 0.8f, 0.6f };
        doc.setLight(index, l, LightField::Color);
        l.spotInnerDeg = 60.0f;
        l.spotOuterDeg = 60.0f;
        doc.setLight(index, l, LightField::SpotInner);
        QCOMPARE(undo->count(), 5);
        QCOMPARE(undo->text(3), QStringLiteral("Light colour of Point light 1"));
        const LightNode edited = light();

        undo->undo();
        QCOMPARE(light().spotInnerDeg, before.spotInnerDeg);
        QCOMPARE(light().spotOuterDeg, before.spotOuterDeg);
        undo->undo();
        QCOMPARE(light().color, before.color);
        undo->undo();
        QCOMPARE(light().position, glm::vec3(0.75f, before.position.y, before.position.z));
        // Undoing X leaves the intensity as typed.
        undo->undo();
        QCOMPARE(light().position, before.position);
        QCOMPARE(light().intensity, 25.0f);
        undo->undo();
        QVERIFY(light() == before);
        undo->setIndex(undo->count());
        QVERIFY(light() == edited);
    }

    void lightMergesStopAtGesturesAndSingleShotFields()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        doc.addLight(LightNode {});
        doc.undoStack()->clear();
        QUndoStack* undo = doc.undoStack();
        const int index = int(doc.state().lights.size()) - 1;
        const LightNode before = doc.state().lights[std::size_t(index)];
        LightNode l = before;

        l.intensity = 2.0f;
        doc.setLight(index, l, LightField::Intensity);
        doc.endEditGesture();
        l.intensity = 3.0f;
        doc.setLight(index, l, LightField::Intensity);
        QCOMPARE(undo->count(), 2);
        // Renames, type changes and shadow switches never merge.
        for (const QString& name : { QStringLiteral("Key"), QStringLiteral("Fill") }) {
            l.name = name;
            doc.setLight(index, l, LightField::Name);
        }
        QCOMPARE(undo->count(), 4);
        QCOMPARE(undo->text(3), QStringLiteral("Rename light Key"));
        for (bool shadows : { false, true }) {
            l.castsShadows = shadows;
            doc.setLight(index, l, LightField::Shadows);
        }
        QCOMPARE(undo->count(), 6);
        // A rect names its fields as the panel does.
        l.type = LightType::Rect;
        doc.setLight(index, l, LightField::Type);
        l.intensity = 9.0f;
        doc.setLight(index, l, LightField::Intensity);
        QCOMPARE(undo->text(7), QStringLiteral("Light radiance of Fill"));
        undo->setIndex(0);
        QVERIFY(doc.state().lights[std::size_t(index)] == before);
    }

    void gestureEndSplitsTransformDrags()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        const NodeTransform before = doc.state().nodes[0].transform;
        NodeTransform t = before;
        for (float y : { 0.1f, 0.2f }) {
            t.translation.y = y;
            doc.setNodeTransform(0, t);
        }
        doc.endEditGesture(); // the mouse button released
        t.translation.y = 0.3f;
        doc.setNodeTransform(0, t);
        QCOMPARE(doc.undoStack()->count(), 2);
        doc.undoStack()->undo();
        QCOMPARE(doc.state().nodes[0].transform.translation.y, 0.2f);
        doc.undoStack()->undo();
        QVERIFY(doc.state().nodes[0].transform == before);
    }

    void hidingANodeRemovesItsMesh()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        EventLog log(doc);
        const std::size_t trianglesBefore = doc.buildRenderScene().triangleCount();
        const std::size_t meshTriangles = doc.sourceScene(0).meshes[2].triangleCount();
        doc.setNodeVisible(2, false);
        QVERIFY(log.contains(ChangeEvent::Kind::Structure, 2));
        std::vector<int> meshToNode;
        const auto scene = doc.buildRenderScene(&meshToNode);
        QCOMPARE(scene.triangleCount(), trianglesBefore - meshTriangles);
        QVERIFY(std::find(meshToNode.begin(), meshToNode.end(), 2) == meshToNode.end());
        QCOMPARE(meshToNode.size(), doc.state().nodes.size() - 1);

        log.events.clear();
        doc.setNodeName(2, QStringLiteral("Tall box"));
        QCOMPARE(log.events.size(), std::size_t(1));
        QVERIFY(log.contains(ChangeEvent::Kind::NodeProperty, 2));
        QCOMPARE(doc.undoStack()->text(1),
            QStringLiteral("Rename %1 to Tall box").arg(doc.sourceScene(0).meshes[2].name.c_str()));
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.buildRenderScene().triangleCount(), trianglesBefore);
    }

    void transformMovesTheRenderedMesh()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        EventLog log(doc);
        doc.setNodeTransform(0, { { 1.0f, 2.0f, 3.0f }, glm::vec3(0.0f), glm::vec3(1.0f) });
        QVERIFY(log.contains(ChangeEvent::Kind::NodeTransform, 0));
        const auto scene = doc.buildRenderScene();
        const glm::mat4 expected = doc.nodeWorldTransform(0);
        QCOMPARE(scene.meshes[0].transform, expected);
        QCOMPARE(glm::vec3(expected[3]),
            glm::vec3(1.0f, 2.0f, 3.0f) + glm::vec3(doc.sourceScene(0).meshes[0].transform[3]));

        // T * Rz * Ry * Rx * S: a 90 degree turn about z takes +x to +y, after scaling.
        NodeTransform t;
        t.rotationDeg = { 0.0f, 0.0f, 90.0f };
        t.scale = glm::vec3(2.0f);
        const glm::vec4 p = t.matrix() * glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
        QVERIFY(std::abs(p.x) < 1e-5f && std::abs(p.y - 2.0f) < 1e-5f);
    }

    void deleteAndDuplicateKeepSelectionSensible()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        QSignalSpy selection(&doc, &Document::selectionChanged);
        const DocumentState before = doc.state();
        const int count = int(before.nodes.size());

        doc.setSelectedNode(3);
        QCOMPARE(selection.count(), 1);
        QCOMPARE(selection.last().at(0).toInt(), 3);
        EventLog log(doc);
        doc.deleteNode(1);
        QVERIFY(log.contains(ChangeEvent::Kind::Structure, 1));
        QCOMPARE(int(doc.state().nodes.size()), count - 1);
        QCOMPARE(doc.selectedNode(), 2); // follows its node
        QCOMPARE(doc.state().nodes[2].id, before.nodes[3].id);
        doc.undoStack()->undo();
        QVERIFY(sameDocument(before, doc.state()));
        QCOMPARE(doc.selectedNode(), 3);

        doc.deleteNode(3);
        QCOMPARE(doc.selectedNode(), -1);
        doc.undoStack()->undo();
        QCOMPARE(doc.selectedNode(), 3);

        doc.duplicateNode(3);
        QCOMPARE(int(doc.state().nodes.size()), count + 1);
        QCOMPARE(doc.selectedNode(), 4);
        const auto& copy = doc.state().nodes[4];
        QCOMPARE(copy.mesh, before.nodes[3].mesh);
        QCOMPARE(copy.id, before.nextId);
        QVERIFY(copy.name.startsWith(before.nodes[3].name));
        QCOMPARE(doc.state().nextId, before.nextId + 1);
        QCOMPARE(doc.buildRenderScene().triangleCount(),
            doc.sourceScene(0).triangleCount()
                + doc.sourceScene(0).meshes[std::size_t(copy.mesh)].triangleCount());
        // The copy stands beside the original, not inside it: their boxes do not overlap along x.
        const vct::render::Aabb original = doc.nodeWorldBounds(3), duplicate = doc.nodeWorldBounds(4);
        QVERIFY(!original.isEmpty());
        QVERIFY2(duplicate.min.x > original.max.x,
            qPrintable(QStringLiteral("%1 > %2").arg(duplicate.min.x).arg(original.max.x)));
        QCOMPARE(duplicate.min.y, original.min.y);
        doc.undoStack()->undo();
        QCOMPARE(doc.selectedNode(), 3);
        QVERIFY(sameDocument(before, doc.state()));
    }

    void importModelAddsAndUndoRemoves()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        const QString obj
            = writeTriangleObj(vct::test::outputDir() + QStringLiteral("/document"), QStringLiteral("wedge"));
        QVERIFY(!obj.isEmpty());
        const DocumentState before = doc.state();
        const std::size_t trianglesBefore = doc.buildRenderScene().triangleCount();
        EventLog log(doc);

        QString error;
        QVERIFY2(doc.importModel(obj, &error), qPrintable(error));
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(doc.undoStack()->text(0).contains(QStringLiteral("wedge.obj")));
        QVERIFY(log.contains(ChangeEvent::Kind::Reset, -1));
        const DocumentState& s = doc.state();
        QCOMPARE(s.sources.size(), std::size_t(2));
        QCOMPARE(s.sources[1].spec, QFileInfo(obj).absoluteFilePath());
        QCOMPARE(s.nodes.size(), before.nodes.size() + 1);
        QCOMPARE(s.materials.size(), before.materials.size() + 1);
        const auto& node = s.nodes.back();
        QCOMPARE(node.source, 1);
        QCOMPARE(node.material, int(before.materials.size()));
        QCOMPARE(s.materials.back().name, std::string("imported_red"));
        QVERIFY(node.id >= before.nextId);
        QCOMPARE(doc.buildRenderScene().triangleCount(), trianglesBefore + 1);

        doc.undoStack()->undo();
        QVERIFY(sameDocument(before, doc.state()));
        QCOMPARE(doc.buildRenderScene().triangleCount(), trianglesBefore);
        doc.undoStack()->redo();
        QCOMPARE(doc.buildRenderScene().triangleCount(), trianglesBefore + 1);

        QVERIFY(!doc.importModel(QStringLiteral("/no/such/model.obj"), &error));
        QVERIFY(error.contains(QStringLiteral("model.obj")));
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    void texturesOfImportedModelsAreRemapped()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        const QString folder = vct::test::outputDir() + QStringLiteral("/document");
        const QString red = writeTexturedObj(folder, QStringLiteral("red_quad"), QColor(255, 0, 0));
        const QString blue = writeTexturedObj(folder, QStringLiteral("blue_quad"), QColor(0, 0, 255));
        QVERIFY(!red.isEmpty() && !blue.isEmpty());
        const std::size_t baseTextures = doc.sourceScene(0).textures.size();
        QString error;
        QVERIFY2(doc.importModel(red, &error), qPrintable(error));
        QVERIFY2(doc.importModel(blue, &error), qPrintable(error));

        std::vector<int> meshToNode;
        const vct::render::Scene scene = doc.buildRenderScene(&meshToNode);
        QCOMPARE(scene.textures.size(), baseTextures + 2);
        auto textureOfNode = [&](int node) -> const vct::render::TextureImage& {
            const int mesh = int(std::find(meshToNode.begin(), meshToNode.end(), node) - meshToNode.begin());
            const int texture
                = scene.materials[std::size_t(scene.meshes[std::size_t(mesh)].material)].albedoTexture;
            return scene.textures.at(std::size_t(texture));
        };
        const int nodes = int(doc.state().nodes.size());
        const auto& redTexture = textureOfNode(nodes - 2);
        const auto& blueTexture = textureOfNode(nodes - 1);
        QCOMPARE(int(redTexture.rgba[0]), 255);
        QCOMPARE(int(redTexture.rgba[2]), 0);
        QCOMPARE(int(blueTexture.rgba[0]), 0);
        QCOMPARE(int(blueTexture.rgba[2]), 255);
    }

    void saveMakesTheDocumentClean()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        QSignalSpy pathSpy(&doc, &Document::filePathChanged);
        doc.setNodeName(0, QStringLiteral("Floor"));
        QVERIFY(doc.isModified());
        const QString path = vct::test::outputDir() + QStringLiteral("/document/clean.vctproj");
        QDir().mkpath(QFileInfo(path).absolutePath());
        QString error;
        QVERIFY2(doc.saveProject(path, &error), qPrintable(error));
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.filePath(), QFileInfo(path).absoluteFilePath());
        QCOMPARE(pathSpy.count(), 1);
        doc.setNodeName(0, QStringLiteral("Ground"));
        QVERIFY(doc.isModified());
        doc.undoStack()->undo();
        QVERIFY(!doc.isModified());
    }

    void cameraIsNotAnEdit()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        EventLog log(doc);
        auto camera = doc.state().camera;
        camera.position.x += 1.0f;
        doc.setCamera(camera);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(log.contains(ChangeEvent::Kind::Camera, -1));
        QCOMPARE(doc.state().camera.position, camera.position);
        QCOMPARE(doc.buildRenderScene().camera.position, camera.position);
    }

    void failedNewSceneLeavesTheDocument()
    {
        Document doc;
        QVERIFY(openCornell(doc));
        doc.setNodeName(0, QStringLiteral("Floor"));
        const DocumentState before = doc.state();
        QString error;
        QVERIFY(!doc.newFromScene(QStringLiteral("builtin:no_such_scene"), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(sameDocument(before, doc.state()));
        QCOMPARE(doc.undoStack()->count(), 1);
    }
};

QTEST_GUILESS_MAIN(tst_Document)
#include "tst_Document.moc"
