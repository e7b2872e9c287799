#pragma once

#include "ChangeEvent.h"
#include "DocumentState.h"
#include "LightField.h"
#include "MaterialField.h"
#include "NodeTransformField.h"
#include "SceneLoader.h"

#include "scene/Scene.h"

#include <QObject>
#include <QUndoStack>

#include <map>
#include <utility>
#include <vector>

namespace vct::doc {

/**
 * The open document: plain state plus the undo stack. Every edit goes through a QUndoCommand; the
 * `set...` helpers push one (slider drags merge into one step). Views and SceneSync listen to `changed`.
 * Knows nothing about GL or widgets.
 */
class Document : public QObject {
    Q_OBJECT

public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    const DocumentState& state() const { return m_state; }
    QUndoStack* undoStack() { return &m_undoStack; }

    /**
     * Starts a new untitled document from a scene spec (builtin:NAME or a model path). Clears undo.
     * `unitScale` is metres per unit of a model file (SceneLoader::load); a model whose up axis `up` is not
     * ours is stood upright by its nodes' placement (a rotation the Transform panel shows).
     */
    bool newFromScene(const QString& spec, QString* error, float unitScale = 1.0f,
        SceneLoader::UpAxis up = SceneLoader::UpAxis::Y);
    /**
     * Opens a .vctproj. On failure the open document is untouched and `error` names the file and problem. A
     * project without nodes and materials gets one node per mesh of each source and the sources' materials,
     * as importModel makes them.
     */
    bool openProject(const QString& path, QString* error);
    /**
     * The folder relative model paths in projects are read from and saved to, instead of the project's own
     * folder (ProjectFile); empty for the project's folder. Kept for every later open and save.
     */
    void setModelRoot(const QString& root) { m_modelRoot = root; }
    QString modelRoot() const { return m_modelRoot; }
    /**
     * Opens an autosaved copy as recovered work: untitled and modified, so that Save asks where to keep it
     * and closing asks first. The copy itself is left in place; the caller removes it once the work is saved.
     */
    bool recoverProject(const QString& path, QString* error);
    /** Saves atomically; a failure leaves any old file whole. On success the document becomes clean. */
    bool saveProject(const QString& path, QString* error);
    /**
     * Adds a model's meshes, materials and lights as one undoable step; `unitScale` is metres per model
     * unit. The same file at another scale is another source. A model whose up axis `up` is not ours is
     * stood upright by its nodes' placement.
     */
    bool importModel(const QString& path, QString* error, float unitScale = 1.0f,
        SceneLoader::UpAxis up = SceneLoader::UpAxis::Y);
    /**
     * The second half of importModel, for a model already loaded with SceneLoader at `unitScale` (on a
     * worker thread, so the UI stays responsive): adds it as one undoable step. False for an unusable scale.
     */
    bool addImportedModel(const QString& path, render::Scene loaded, float unitScale = 1.0f,
        SceneLoader::UpAxis up = SceneLoader::UpAxis::Y);

    QString filePath() const { return m_filePath; }
    /** What the last newFromScene() added on its own (a light for a model that brought none), for the status
     * bar; empty when nothing. */
    QString openNote() const { return m_openNote; }
    bool isModified() const { return !m_undoStack.isClean(); }

    // Edits: each pushes one undo command.
    /**
     * `field` is the part the edit changes: consecutive edits of the same field of a node merge into one
     * step, an edit of another field is a step of its own (NodeTransformField).
     */
    void setNodeTransform(
        int node, const NodeTransform& transform, NodeTransformField field = NodeTransformField::Whole);
    void setNodeName(int node, const QString& name);
    void setNodeVisible(int node, bool visible);
    void setNodeDynamic(int node, bool dynamic);
    void duplicateNode(int node);
    void deleteNode(int node);
    /** `field` as for setNodeTransform: runs of edits of one field of a material merge (MaterialField). */
    void setMaterial(int index, const render::Material& material, MaterialField field = MaterialField::Whole);
    /** `field` as for setNodeTransform: runs of edits of one field of a light merge (LightField). */
    void setLight(int index, const LightNode& light, LightField field = LightField::Whole);
    void addLight(const LightNode& light);
    void removeLight(int index);
    void setSettings(const render::RenderSettings& settings);
    /** Not undoable: moving the view is not an edit (as in Blender and Godot); saved with the project. */
    void setCamera(const render::Camera& camera);
    /** Keeps the current camera as a bookmark named `name` (empty: "View N"); one undo step. */
    void addBookmark(const QString& name = {});
    /** Forgets bookmark `index`; one undo step. */
    void removeBookmark(int index);
    /**
     * The camera as the scene or project was opened or last saved, for View > Reset camera. A copy apart from
     * state().camera, because that one is what the view moves: after the first orbit it no longer says where
     * the document's own camera is.
     */
    const render::Camera& savedCamera() const { return m_savedCamera; }

    /**
     * Ends the gesture the last edit belonged to (Enter or focus leaving a spin box, a colour dialog
     * closing, a drag released): the next edit is an undo step of its own even when it changes the same
     * field again. An undo ends it too, so an edit after an undo never merges into the step below.
     */
    void endEditGesture() { ++m_editGesture; }
    /** The current gesture's number, for merging commands: only edits of one gesture merge. */
    quint64 editGesture() const { return m_editGesture; }

    /** Current selection (a node index or -1); not part of undo. */
    int selectedNode() const { return m_selectedNode; }
    void setSelectedNode(int node);
    /** The selected node's id, or 0 when nothing is selected. */
    quint64 selectedNodeId() const;
    /** Selects the node with this id, or nothing (-1) when no node has it. */
    void selectNodeById(quint64 id);

    /** Index of the node with this id, or -1. */
    int nodeIndex(quint64 id) const;
    /** Index of the light with this id, or -1. */
    int lightIndex(quint64 id) const;

    /**
     * The scene the renderers draw: visible nodes only, each mesh transformed by its node. meshToNode, if
     * given, receives for each renderer mesh the node index it came from. With @p hidden, hidden nodes'
     * meshes are there too, marked invisible (render::Mesh::visible), so that showing one again needs no new
     * scene.
     */
    render::Scene buildRenderScene(std::vector<int>* meshToNode = nullptr, bool hidden = false) const;
    /** World transform of a node's mesh (node transform times the imported one). */
    glm::mat4 nodeWorldTransform(int node) const;
    /** World-space bounds of a node's mesh, metres; empty for a node without geometry. */
    render::Aabb nodeWorldBounds(int node) const;
    /** World-space bounds of every visible node's geometry, metres. */
    render::Aabb sceneBounds() const;
    /** The imported geometry of a source (cached when the source was loaded). */
    const render::Scene& sourceScene(int source) const;

    /** For undo commands: replace part of the state and announce it. Not for views. */
    DocumentState& mutableState() { return m_state; }
    void notify(const ChangeEvent& event);

signals:
    void changed(const vct::doc::ChangeEvent& event);
    void selectionChanged(int node);
    void filePathChanged(const QString& path);

private:
    /// A source's spec and unit scale: one file at two scales is two different geometries.
    using GeometryKey = std::pair<QString, float>;
    static GeometryKey geometryKey(const SceneSource& source) { return { source.spec, source.unitScale }; }

    DocumentState m_state;
    std::map<GeometryKey, render::Scene> m_geometry; ///< Imported scenes, already scaled, by source.
    QString m_modelRoot;
    QUndoStack m_undoStack;
    QString m_filePath;
    QString m_openNote;
    render::Camera m_savedCamera;
    int m_selectedNode = -1;
    quint64 m_editGesture = 0;
    int m_undoIndex = 0; ///< The undo stack's index as last seen, to tell an undo from a push.
};

} // namespace vct::doc
