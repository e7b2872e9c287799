#include "ModelImporter.h"

#include "GltfEmissiveStrength.h"
#include "ModelPreflight.h"
#include "QtAssimpIOSystem.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <QDir>
#include <QFileInfo>
#include <QHash>
#include <QImage>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace vct::doc {

namespace {

constexpr float kDielectricSpecular = 0.04f;
constexpr float kMinRoughness = 0.02f;
// A triangle whose doubled area is below this share of its longest squared edge has an angle under ~1e-6 rad.
constexpr float kDegenerateRatio = 1e-6f;

/** Everything one import needs while walking Assimp's scene. */
struct ImportState {
    const aiScene* ai = nullptr;
    QString path;
    QDir modelDir;
    bool gltf = false;
    std::vector<GltfEmissiveStrength::Entry> emissiveStrengths;
    render::Scene* scene = nullptr;
    const QtAssimpIOSystem* files = nullptr; // Decides which referenced files may be read.
    ImportReport report;
    std::vector<int> materialMap; // Assimp material index -> scene material index, -1 until first used.
    QHash<QString, int> textureMap; // texture reference -> scene texture index (-1 if it failed to load).
};

bool isFinite(const aiVector3D& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::vec3 toGlm(const aiVector3D& v)
{
    return { v.x, v.y, v.z };
}

glm::vec3 toGlm(const aiColor3D& c)
{
    return { c.r, c.g, c.b };
}

glm::mat4 toGlm(const aiMatrix4x4& m)
{
    // Assimp matrices are row-major, glm's column-major.
    glm::mat4 result;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column)
            result[column][row] = m[row][column];
    return result;
}

aiColor3D colorOr(
    const aiMaterial* material, const char* key, unsigned type, unsigned index, aiColor3D fallback)
{
    aiColor3D color;
    return material->Get(key, type, index, color) == AI_SUCCESS ? color : fallback;
}

float floatOr(const aiMaterial* material, const char* key, unsigned type, unsigned index, float fallback)
{
    float value = 0.0f;
    return material->Get(key, type, index, value) == AI_SUCCESS ? value : fallback;
}

/**
 * Names nobody gave: Assimp's OBJ loader calls the geometry of a file without `o`/`g` lines "defaultobject",
 * other loaders make up bracketed names such as "<STL_BINARY>", and many files leave names empty.
 */
bool isPlaceholderName(const QString& name)
{
    return name.isEmpty() || name == QLatin1String("defaultobject")
        || (name.startsWith(QLatin1Char('<')) && name.endsWith(QLatin1Char('>')));
}

/**
 * "node/mesh" without the made-up parts, and once when both parts say the same (an OBJ's `o floor` becomes
 * node "floor" holding mesh "floor"). Empty when neither part is a real name: importModel() then names the
 * mesh after the file.
 */
QString meshName(const QString& nodeName, const QString& ownName)
{
    const QString node = isPlaceholderName(nodeName) ? QString() : nodeName;
    const QString own = isPlaceholderName(ownName) || ownName == node ? QString() : ownName;
    if (node.isEmpty() || own.isEmpty())
        return node.isEmpty() ? own : node;
    return node + QLatin1Char('/') + own;
}

/**
 * Names the unnamed meshes from index `first` on after the file: "bunny", then "bunny 2", ... when several
 * would share it, skipping names the file itself gave in the same import.
 */
void nameAfterFile(render::Scene& scene, std::size_t first, const QString& baseName)
{
    const std::string stem = baseName.isEmpty() ? std::string("mesh") : baseName.toStdString();
    std::set<std::string> taken;
    for (std::size_t i = first; i < scene.meshes.size(); ++i)
        taken.insert(scene.meshes[i].name);
    int number = 1;
    for (std::size_t i = first; i < scene.meshes.size(); ++i) {
        if (!scene.meshes[i].name.empty())
            continue;
        std::string name;
        do {
            name = number == 1 ? stem : stem + ' ' + std::to_string(number);
            ++number;
        } while (taken.count(name) > 0);
        taken.insert(name);
        scene.meshes[i].name = name;
    }
}

int storeTexture(ImportState& state, const QImage& decoded, const QString& name)
{
    const QImage image = decoded.convertToFormat(QImage::Format_RGBA8888);
    render::TextureImage texture;
    texture.name = name.toStdString();
    texture.width = image.width();
    texture.height = image.height();
    const qsizetype rowBytes = qsizetype(image.width()) * 4;
    texture.rgba.resize(size_t(rowBytes) * size_t(image.height()));
    for (int y = 0; y < image.height(); ++y)
        std::copy_n(image.constScanLine(y), rowBytes, texture.rgba.begin() + qsizetype(y) * rowBytes);
    state.scene->textures.push_back(std::move(texture));
    return int(state.scene->textures.size()) - 1;
}

QImage decodeEmbedded(const aiTexture* texture)
{
    if (texture->mHeight == 0) {
        // Compressed (PNG, JPEG, ...): mWidth is the byte count.
        return QImage::fromData(reinterpret_cast<const uchar*>(texture->pcData), int(texture->mWidth));
    }
    QImage image(int(texture->mWidth), int(texture->mHeight), QImage::Format_RGBA8888);
    for (unsigned y = 0; y < texture->mHeight; ++y) {
        uchar* row = image.scanLine(int(y));
        for (unsigned x = 0; x < texture->mWidth; ++x) {
            const aiTexel& texel = texture->pcData[y * texture->mWidth + x];
            row[4 * x + 0] = texel.r;
            row[4 * x + 1] = texel.g;
            row[4 * x + 2] = texel.b;
            row[4 * x + 3] = texel.a;
        }
    }
    return image;
}

int loadTexture(ImportState& state, const aiString& reference)
{
    const QString key = QString::fromUtf8(reference.C_Str());
    const auto cached = state.textureMap.constFind(key);
    if (cached != state.textureMap.constEnd())
        return cached.value();

    int index = -1;
    if (const aiTexture* embedded = state.ai->GetEmbeddedTexture(reference.C_Str())) {
        const QImage image = decodeEmbedded(embedded);
        if (image.isNull())
            state.report.warnings
                << QStringLiteral("%1: embedded texture %2 could not be decoded").arg(state.path, key);
        else
            index = storeTexture(state, image, key);
    } else {
        QString file = key;
        file.replace(QLatin1Char('\\'), QLatin1Char('/'));
        if (QFileInfo(file).isRelative())
            file = state.modelDir.filePath(file);
        const QString refusal = state.files->refusalReason(file);
        const QImage image = refusal.isEmpty() ? QImage(file) : QImage();
        if (!refusal.isEmpty())
            state.report.warnings
                << QStringLiteral("%1: texture %2 was not read: %3").arg(state.path, file, refusal);
        else if (image.isNull())
            state.report.warnings
                << QStringLiteral("%1: texture %2 is missing or unreadable").arg(state.path, file);
        else
            index = storeTexture(state, image, key);
    }
    state.textureMap.insert(key, index);
    return index;
}

void convertGltfSurface(const aiMaterial* source, render::Material& material)
{
    aiColor4D base(1.0f, 1.0f, 1.0f, 1.0f);
    if (source->Get(AI_MATKEY_BASE_COLOR, base) != AI_SUCCESS)
        source->Get(AI_MATKEY_COLOR_DIFFUSE, base);
    const glm::vec3 baseColor(base.r, base.g, base.b);
    // glTF's defaults when the factors are absent.
    const float metallic = std::clamp(floatOr(source, AI_MATKEY_METALLIC_FACTOR, 1.0f), 0.0f, 1.0f);
    const float roughness
        = std::clamp(floatOr(source, AI_MATKEY_ROUGHNESS_FACTOR, 1.0f), kMinRoughness, 1.0f);

    material.albedo = baseColor * (1.0f - metallic);
    material.specular = glm::mix(glm::vec3(kDielectricSpecular), baseColor, metallic);
    const float a = roughness * roughness;
    const float shininess = std::min(2.0f / (a * a) - 2.0f, ModelImporter::kMaxShininess);
    if (shininess >= 1.0f) {
        material.shininess = shininess;
    } else {
        material.albedo += material.specular;
        material.specular = glm::vec3(0.0f);
        material.shininess = 0.0f;
    }
}

void convertPhongSurface(const aiMaterial* source, render::Material& material)
{
    material.albedo = toGlm(colorOr(source, AI_MATKEY_COLOR_DIFFUSE, aiColor3D(0.8f, 0.8f, 0.8f)));
    material.specular = toGlm(colorOr(source, AI_MATKEY_COLOR_SPECULAR, aiColor3D(0.0f, 0.0f, 0.0f)));
    // Assimp reports a default shininess even when the file has none; it only means something with Ks.
    const bool hasSpecular
        = material.specular.x > 0.0f || material.specular.y > 0.0f || material.specular.z > 0.0f;
    const float shininess = floatOr(source, AI_MATKEY_SHININESS, 0.0f);
    material.shininess = hasSpecular && std::isfinite(shininess)
        ? std::clamp(shininess, 0.0f, ModelImporter::kMaxShininess)
        : 0.0f;
}

glm::vec3 sanitize(const glm::vec3& color)
{
    glm::vec3 result;
    for (int c = 0; c < 3; ++c)
        result[c] = std::isfinite(color[c]) ? std::max(color[c], 0.0f) : 0.0f;
    return result;
}

int sceneMaterial(ImportState& state, unsigned aiIndex)
{
    if (aiIndex >= state.materialMap.size())
        aiIndex = 0;
    if (state.materialMap.empty())
        return 0;
    if (state.materialMap[aiIndex] >= 0)
        return state.materialMap[aiIndex];

    const aiMaterial* source = state.ai->mMaterials[aiIndex];
    render::Material material;
    aiString name;
    if (source->Get(AI_MATKEY_NAME, name) == AI_SUCCESS)
        material.name = name.C_Str();
    if (state.gltf)
        convertGltfSurface(source, material);
    else
        convertPhongSurface(source, material);
    material.albedo = sanitize(material.albedo);
    material.specular = sanitize(material.specular);
    // glTF says whether a material is double-sided (Assimp: AI_MATKEY_TWOSIDED); formats that do not, stay
    // so.
    int twoSided = 1;
    if (source->Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS)
        material.doubleSided = twoSided != 0;

    material.emission
        = sanitize(toGlm(colorOr(source, AI_MATKEY_COLOR_EMISSIVE, aiColor3D(0.0f, 0.0f, 0.0f))));
    if (state.gltf)
        material.emission *= GltfEmissiveStrength::strengthFor(
            state.emissiveStrengths, QString::fromUtf8(name.C_Str()), aiIndex);

    bool clamped = false;
    for (int c = 0; c < 3; ++c) {
        const float sum = material.albedo[c] + material.specular[c];
        if (sum > 1.0f) {
            material.albedo[c] /= sum;
            material.specular[c] /= sum;
            clamped = true;
        }
    }
    if (clamped) {
        ++state.report.clampedMaterials;
        state.report.warnings << QStringLiteral(
            "%1: material '%2' reflects more than it receives (albedo + specular "
            "> 1); scaled down")
                                     .arg(state.path, QString::fromStdString(material.name));
    }

    aiString texture;
    if (source->GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS
        || source->GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS)
        material.albedoTexture = loadTexture(state, texture);

    state.scene->materials.push_back(std::move(material));
    state.materialMap[aiIndex] = int(state.scene->materials.size()) - 1;
    return state.materialMap[aiIndex];
}

void appendMesh(ImportState& state, const aiMesh* source, const glm::mat4& transform, const QString& nodeName)
{
    if (!(source->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) {
        ++state.report.ignoredMeshes;
        return;
    }
    const unsigned vertexCount = source->mNumVertices;
    std::vector<std::uint32_t> triangles;
    triangles.reserve(size_t(source->mNumFaces) * 3);
    ImportReport& report = state.report;
    for (unsigned f = 0; f < source->mNumFaces; ++f) {
        const aiFace& face = source->mFaces[f];
        if (face.mNumIndices != 3)
            continue; // Points and lines that SortByPType left in a mixed mesh.
        const unsigned a = face.mIndices[0], b = face.mIndices[1], c = face.mIndices[2];
        if (a >= vertexCount || b >= vertexCount || c >= vertexCount) {
            ++report.badIndexTriangles;
            continue;
        }
        if (!isFinite(source->mVertices[a]) || !isFinite(source->mVertices[b])
            || !isFinite(source->mVertices[c])) {
            ++report.nonFiniteTriangles;
            continue;
        }
        const glm::vec3 e1 = toGlm(source->mVertices[b]) - toGlm(source->mVertices[a]);
        const glm::vec3 e2 = toGlm(source->mVertices[c]) - toGlm(source->mVertices[a]);
        const glm::vec3 e3 = e2 - e1;
        const float longest = std::max({ glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3) });
        const float doubledArea = glm::length(glm::cross(e1, e2));
        if (!(doubledArea > kDegenerateRatio * longest)) {
            ++report.zeroAreaTriangles;
            continue;
        }
        triangles.insert(triangles.end(), { a, b, c });
    }
    report.droppedTriangles = report.nonFiniteTriangles + report.badIndexTriangles + report.zeroAreaTriangles;
    if (triangles.empty())
        return;

    // Face normals, area weighted, for vertices whose own normal is unusable.
    std::vector<glm::vec3> faceSum(vertexCount, glm::vec3(0.0f));
    for (size_t t = 0; t < triangles.size(); t += 3) {
        const glm::vec3 p0 = toGlm(source->mVertices[triangles[t]]);
        const glm::vec3 n = glm::cross(
            toGlm(source->mVertices[triangles[t + 1]]) - p0, toGlm(source->mVertices[triangles[t + 2]]) - p0);
        for (int k = 0; k < 3; ++k)
            faceSum[triangles[t + k]] += n;
    }

    std::vector<std::uint32_t> remap(vertexCount, ~0u);
    for (std::uint32_t index : triangles)
        remap[index] = 0;
    render::Mesh mesh;
    mesh.name = meshName(nodeName, QString::fromUtf8(source->mName.C_Str())).toStdString();
    const bool hasUvs = source->HasTextureCoords(0);
    for (unsigned v = 0; v < vertexCount; ++v) {
        if (remap[v] == ~0u)
            continue;
        remap[v] = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(toGlm(source->mVertices[v]));
        glm::vec3 normal = source->HasNormals() ? toGlm(source->mNormals[v]) : glm::vec3(0.0f);
        const float length = glm::length(normal);
        if (!std::isfinite(length) || length < 1e-12f) {
            ++state.report.repairedNormals;
            const float faceLength = glm::length(faceSum[v]);
            normal = faceLength > 0.0f ? faceSum[v] / faceLength : glm::vec3(0.0f, 1.0f, 0.0f);
        } else {
            normal /= length;
        }
        mesh.normals.push_back(normal);
        if (hasUvs) {
            const aiVector3D& uv = source->mTextureCoords[0][v];
            mesh.uvs.emplace_back(std::isfinite(uv.x) ? uv.x : 0.0f, std::isfinite(uv.y) ? uv.y : 0.0f);
        }
    }
    // A mirroring transform turns counter-clockwise into clockwise; swap two corners to keep front faces.
    const bool mirrored = glm::determinant(glm::mat3(transform)) < 0.0f;
    mesh.indices.reserve(triangles.size());
    for (size_t t = 0; t < triangles.size(); t += 3) {
        mesh.indices.push_back(remap[triangles[t]]);
        mesh.indices.push_back(remap[triangles[t + (mirrored ? 2 : 1)]]);
        mesh.indices.push_back(remap[triangles[t + (mirrored ? 1 : 2)]]);
    }
    mesh.transform = transform;
    mesh.material = sceneMaterial(state, source->mMaterialIndex);

    state.report.triangles += int(mesh.triangleCount());
    ++state.report.meshes;
    state.scene->meshes.push_back(std::move(mesh));
}

void appendNode(ImportState& state, const aiNode* node, const glm::mat4& parent)
{
    const glm::mat4 transform = parent * toGlm(node->mTransformation);
    const QString name = QString::fromUtf8(node->mName.C_Str());
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        if (node->mMeshes[i] < state.ai->mNumMeshes)
            appendMesh(state, state.ai->mMeshes[node->mMeshes[i]], transform, name);
    }
    for (unsigned i = 0; i < node->mNumChildren; ++i)
        appendNode(state, node->mChildren[i], transform);
}

void mergeReport(const ImportReport& from, ImportReport* into)
{
    if (!into)
        return;
    into->meshes += from.meshes;
    into->triangles += from.triangles;
    into->droppedTriangles += from.droppedTriangles;
    into->nonFiniteTriangles += from.nonFiniteTriangles;
    into->badIndexTriangles += from.badIndexTriangles;
    into->zeroAreaTriangles += from.zeroAreaTriangles;
    into->repairedNormals += from.repairedNormals;
    into->clampedMaterials += from.clampedMaterials;
    into->ignoredMeshes += from.ignoredMeshes;
    into->warnings += from.warnings;
}

bool fail(QString* error, const QString& message)
{
    if (error)
        *error = message;
    return false;
}

} // namespace

bool ModelImporter::importModel(
    const QString& path, render::Scene& scene, QString* error, ImportReport* report)
{
    const QFileInfo info(path);
    if (!info.exists())
        return fail(error, QStringLiteral("%1: file not found").arg(path));
    if (!info.isFile())
        return fail(error, QStringLiteral("%1: not a file").arg(path));

    if (const QString problem = ModelPreflight::check(path); !problem.isEmpty())
        return fail(error, QStringLiteral("%1: cannot import model: %2").arg(path, problem));

    QStringList refusals;
    Assimp::Importer importer;
    auto* files = new QtAssimpIOSystem(path, &refusals);
    importer.SetIOHandler(files); // The importer owns and deletes it.
    // Normals a file lacks are made by smoothing across edges below this angle. Assimp's default (175
    // degrees) rounds a box's 90-degree corners, so the Cornell boxes were shaded like pillows: 7x the
    // reference error, by our path tracer and the VCT renderer alike. 80 degrees keeps creases and smooths
    // curved meshes, whose neighbouring faces meet at a few degrees.
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 80.0f);
    const unsigned flags = aiProcess_Triangulate | aiProcess_GenSmoothNormals
        | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType | aiProcess_ValidateDataStructure
        | aiProcess_FlipUVs;
    const aiScene* ai = importer.ReadFile(path.toUtf8().constData(), flags);
    if (!ai || !ai->mRootNode) {
        QString reason = QString::fromUtf8(importer.GetErrorString());
        if (!refusals.isEmpty())
            reason += QStringLiteral(" (") + refusals.join(QStringLiteral("; ")) + QLatin1Char(')');
        return fail(error,
            QStringLiteral("%1: cannot import model: %2")
                .arg(path, reason.isEmpty() ? QStringLiteral("unknown error") : reason));
    }

    ImportState state;
    state.ai = ai;
    state.path = path;
    state.modelDir = info.dir();
    const QString suffix = info.suffix().toLower();
    state.gltf = suffix == QLatin1String("gltf") || suffix == QLatin1String("glb");
    if (state.gltf) {
        QString warning;
        if (!GltfEmissiveStrength::read(path, state.emissiveStrengths, &warning))
            state.report.warnings << warning;
    }
    state.scene = &scene;
    state.files = files;
    for (const QString& refusal : refusals)
        state.report.warnings << QStringLiteral("%1: %2").arg(path, refusal);
    state.materialMap.assign(ai->mNumMaterials, -1);

    const size_t meshesBefore = scene.meshes.size();
    const size_t materialsBefore = scene.materials.size();
    const size_t texturesBefore = scene.textures.size();
    appendNode(state, ai->mRootNode, glm::mat4(1.0f));
    nameAfterFile(scene, meshesBefore, info.completeBaseName());

    if (state.report.ignoredMeshes > 0)
        state.report.warnings << QStringLiteral("%1: %2 point or line meshes ignored")
                                     .arg(path)
                                     .arg(state.report.ignoredMeshes);
    if (state.report.droppedTriangles > 0) {
        QStringList reasons;
        for (const auto& [count, reason] :
            { std::pair { state.report.nonFiniteTriangles, "a non-finite vertex" },
                std::pair { state.report.badIndexTriangles, "a vertex index out of range" },
                std::pair { state.report.zeroAreaTriangles, "zero area" } })
            if (count > 0)
                reasons << QStringLiteral("%1 for %2").arg(count).arg(QLatin1String(reason));
        state.report.warnings << QStringLiteral("%1: %2 triangles dropped: %3")
                                     .arg(path)
                                     .arg(state.report.droppedTriangles)
                                     .arg(reasons.join(QStringLiteral(", ")));
    }
    if (state.report.repairedNormals > 0)
        state.report.warnings << QStringLiteral("%1: %2 missing or invalid normals recomputed")
                                     .arg(path)
                                     .arg(state.report.repairedNormals);
    mergeReport(state.report, report);

    if (state.report.triangles == 0) {
        scene.meshes.resize(meshesBefore);
        scene.materials.resize(materialsBefore);
        scene.textures.resize(texturesBefore);
        return fail(error, QStringLiteral("%1: the model contains no usable triangles").arg(path));
    }
    return true;
}

} // namespace vct::doc

// Debian builds Assimp 5.2 with its internal assertions on (ASSIMP_BUILD_DEBUG), and the default handler
// calls abort(): a model whose data contradicts its header (found by fuzzing: a PLY whose vertex count
// disagrees with its faces trips an assertion in the triangulation step) would take the whole editor down
// with the user's unsaved work. libassimp calls Assimp::aiAssertViolation through its exported symbol, so
// this definition in our program replaces the library's; it throws instead, Importer::ReadFile catches it,
// and the import fails with the assertion as its message.
namespace Assimp {

void aiAssertViolation(const char* failedExpression, const char* file, int line)
{
    throw std::runtime_error(std::string("the model's data is inconsistent (Assimp check failed: ")
        + failedExpression + " in " + file + ":" + std::to_string(line) + ")");
}

} // namespace Assimp
