#include "scene/AssimpReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "base/ChildProcess.h"
#include "base/ExternalReference.h"
#include "base/InputFile.h"
#include "scene/GltfDraco.h"
#include "scene/MeshWeld.h"
#include "tet/MeshMessage.h"
#include "tet/MeshValidation.h"
#include "tet/MeshingMemory.h"

namespace tetglow {
namespace {

// A file's bytes as Assimp reads them; the bytes belong to the FileSystem below.
class ByteStream : public Assimp::IOStream {
public:
    explicit ByteStream(const std::string& bytes) : bytes_(bytes) {}
    size_t Read(void* out, size_t size, size_t count) override {
        if (size == 0) return 0;
        count = std::min(count, (bytes_.size() - pos_) / size);
        std::memcpy(out, bytes_.data() + pos_, size * count);
        pos_ += size * count;
        return count;
    }
    size_t Write(const void*, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        const size_t base = origin == aiOrigin_CUR ? pos_ : origin == aiOrigin_END ? bytes_.size() : 0;
        if (origin == aiOrigin_END ? offset > base : offset > bytes_.size() - base) return aiReturn_FAILURE;
        pos_ = origin == aiOrigin_END ? base - offset : base + offset;
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return pos_; }
    size_t FileSize() const override { return bytes_.size(); }
    void Flush() override {}

private:
    const std::string& bytes_;
    size_t pos_ = 0;
};

// The files Assimp may open: the mesh file itself (already read, under a name of our own whose
// extension picks the importer) and, read on demand through readInputFile, the files it names
// inside the mesh's folder (base/ExternalReference.h). Opening fails (and the first reason is
// kept) for a file outside that folder, for anything readInputFile refuses, for writing, and
// once all files together exceed the mesh limit.
class FileSystem : public Assimp::IOSystem {
public:
    // `mainName`: ours for the mesh file, in its folder.
    FileSystem(const std::string& mainName, std::string data)
        : folder_(std::filesystem::path(mainName).parent_path().string()), total_(data.size()) {
        files_[mainName] = std::move(data);
    }
    bool Exists(const char* name) const override {
        std::error_code ec;
        if (files_.count(name)) return true;
        try {
            return std::filesystem::exists(resolve(name), ec);
        } catch (const InputError&) {
            return false;
        }
    }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* name, const char* mode) override {
        if (std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+')) return nullptr;
        auto it = files_.find(name);
        if (it == files_.end()) {
            try {
                const std::string file = resolve(name).string();
                std::string data = readInputFile(file, kMaxMeshFileBytes - std::min(kMaxMeshFileBytes, total_),
                                                 "the rest of a mesh's files (1024 MiB in all)");
                total_ += data.size();
                read_.push_back(file);
                it = files_.emplace(name, std::move(data)).first;
            } catch (const InputError& e) {
                if (problem_.empty()) problem_ = e.what();
                return nullptr;
            }
        }
        return new ByteStream(it->second);
    }
    void Close(Assimp::IOStream* stream) override { delete stream; }
    // Why a file could not be opened, or "".
    const std::string& problem() const { return problem_; }
    // The files read besides the mesh file itself.
    const std::vector<std::string>& read() const { return read_; }

private:
    // The file a name Assimp asks for leads to. Assimp glues the reference, as the file wrote it,
    // to the folder ("<folder>/" + uri, an absolute uri too): taken off again, it is what the
    // message names and what is resolved.
    std::filesystem::path resolve(const std::string& name) const {
        std::string reference = name;
        if (!folder_.empty() && reference.rfind(folder_ + "/", 0) == 0) reference.erase(0, folder_.size() + 1);
        return resolveReference(folder_, reference);
    }

    const std::string folder_;
    std::string problem_;
    std::vector<std::string> read_;
    std::map<std::string, std::string> files_;
    uint64_t total_ = 0;
};

glm::dmat4 toGlm(const aiMatrix4x4& a) {
    glm::dmat4 m;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) m[col][row] = a[row][col];  // glm is column-major
    return m;
}

struct Placed {
    const aiNode* node;
    glm::dmat4 world;
};

// Every node with its world transform, parents before children (iteratively: the depth of a
// hierarchy is the file's to choose).
std::vector<Placed> placeNodes(const aiNode* root, const std::string& path) {
    std::vector<Placed> nodes, stack{{root, toGlm(root->mTransformation)}};
    while (!stack.empty()) {
        const Placed p = stack.back();
        stack.pop_back();
        nodes.push_back(p);
        if (nodes.size() > kMaxSceneMeshTriangles)
            throw InputError(path + ": more than " + std::to_string(kMaxSceneMeshTriangles) + " nodes");
        for (unsigned c = p.node->mNumChildren; c-- > 0;)  // the first child on top: the file's order
            if (const aiNode* child = p.node->mChildren[c])
                stack.push_back({child, p.world * toGlm(child->mTransformation)});
    }
    return nodes;
}

// Whether `n` is `top` or lies below it.
bool within(const aiNode* n, const aiNode* top) {
    for (; n; n = n->mParent)
        if (n == top) return true;
    return false;
}

// The node named `name` (an InputError naming the choices when there is not exactly one).
const aiNode* findNode(const std::vector<Placed>& nodes, const std::string& name, const std::string& path) {
    const aiNode* found = nullptr;
    size_t count = 0;
    std::string named;  // the nodes with meshes, for the message
    for (const Placed& p : nodes) {
        if (name == p.node->mName.C_Str()) {
            found = p.node;
            ++count;
        }
        if (p.node->mNumMeshes && named.size() < 200)
            named += std::string(named.empty() ? "" : ", ") + "'" + p.node->mName.C_Str() + "'";
    }
    if (count > 1) throw InputError(path + ": " + std::to_string(count) + " nodes are named '" + shorten(name) + "'");
    if (!found)
        throw InputError(path + ": no node named '" + shorten(name) +
                         "' (nodes with meshes: " + (named.empty() ? "none" : shorten(named, 200)) + ")");
    return found;
}

// The world transform of each bone's node, by name.
using BoneWorlds = std::map<std::string, glm::dmat4>;

// A skinned mesh's positions as its skin places them, in the coordinates of the node at `world`:
// each vertex by its bones' node transforms times their offsets (the inverse bind matrices, with
// Collada's bind-shape matrix, which Assimp folds into them), weighted: linear blend skinning, as
// Blender and glTF place a skin. A vertex that no bone found in the scene weighs stays as it is.
std::vector<glm::dvec3> skinnedPositions(const aiMesh& m, const BoneWorlds& bones, const glm::dmat4& world,
                                         const std::string& path) {
    std::vector<glm::dvec3> sum(m.mNumVertices, glm::dvec3(0));
    std::vector<double> weight(m.mNumVertices, 0);
    for (unsigned b = 0; b < m.mNumBones; ++b) {
        const aiBone* bone = m.mBones[b];
        const auto it = bone ? bones.find(bone->mName.C_Str()) : bones.end();
        if (it == bones.end()) continue;
        const glm::dmat4 pose = it->second * toGlm(bone->mOffsetMatrix);
        for (unsigned k = 0; k < bone->mNumWeights; ++k) {
            const aiVertexWeight& w = bone->mWeights[k];
            if (w.mVertexId >= m.mNumVertices || !std::isfinite(w.mWeight))
                throw InputError(path + ": mesh '" + shorten(m.mName.C_Str()) + "': bone '" +
                                 shorten(bone->mName.C_Str()) + "' weighs a vertex that is not there");
            const aiVector3D& p = m.mVertices[w.mVertexId];
            sum[w.mVertexId] += double(w.mWeight) * glm::dvec3(pose * glm::dvec4(p.x, p.y, p.z, 1));
            weight[w.mVertexId] += w.mWeight;
        }
    }
    const glm::dmat4 toNode = glm::inverse(world);
    std::vector<glm::dvec3> out(m.mNumVertices);
    for (unsigned v = 0; v < m.mNumVertices; ++v)
        out[v] = weight[v] > 0 ? glm::dvec3(toNode * glm::dvec4(sum[v] / weight[v], 1))
                               : glm::dvec3(m.mVertices[v].x, m.mVertices[v].y, m.mVertices[v].z);
    return out;
}

// The triangles of the node's meshes in the node's own coordinates (the node at `world`, skins
// posed); counts other faces in `skipped`.
TriangleMesh nodeMesh(const aiScene& scene, const aiNode& node, const glm::dmat4& world, const BoneWorlds& bones,
                      const std::string& path, size_t& skipped) {
    TriangleMesh local;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        if (node.mMeshes[i] >= scene.mNumMeshes)
            throw InputError(path + ": a node names mesh " + std::to_string(node.mMeshes[i]) + " of " +
                             std::to_string(scene.mNumMeshes));
        const aiMesh& m = *scene.mMeshes[node.mMeshes[i]];
        const uint32_t base = uint32_t(local.positions.size());
        if (m.mNumBones) {
            const std::vector<glm::dvec3> posed = skinnedPositions(m, bones, world, path);
            local.positions.insert(local.positions.end(), posed.begin(), posed.end());
        } else {
            for (unsigned v = 0; v < m.mNumVertices; ++v)
                local.positions.emplace_back(m.mVertices[v].x, m.mVertices[v].y, m.mVertices[v].z);
        }
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) {
                ++skipped;
                continue;
            }
            for (unsigned k = 0; k < 3; ++k)
                if (face.mIndices[k] >= m.mNumVertices)
                    throw InputError(path + ": mesh '" + shorten(m.mName.C_Str()) + "': face " + std::to_string(f) +
                                     ": vertex index " + std::to_string(face.mIndices[k]) + " out of range (" +
                                     std::to_string(m.mNumVertices) + " vertices)");
            local.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        }
    }
    weldEqualPositions(local);
    return local;
}

// The triangles the nodes within `top` place, and the largest share of them that one node's
// meshes make by being placed again and again (instancing): counted before anything is
// flattened, so that 960 triangles at 20000 nodes are refused in a moment.
void checkInstancing(const aiScene& scene, const std::vector<Placed>& nodes, const aiNode* top,
                     const std::string& path) {
    std::map<std::vector<unsigned>, size_t> instances;
    size_t total = 0;
    for (const Placed& p : nodes) {
        if (!p.node->mNumMeshes || !within(p.node, top)) continue;
        ++instances[std::vector<unsigned>(p.node->mMeshes, p.node->mMeshes + p.node->mNumMeshes)];
    }
    std::pair<size_t, size_t> largest{0, 0};  // the triangles of one placing, its instances
    for (const auto& [meshes, count] : instances) {
        size_t faces = 0;
        for (unsigned m : meshes)
            if (m < scene.mNumMeshes) faces += scene.mMeshes[m]->mNumFaces;
        total += faces * count;
        if (faces * count > largest.first * largest.second) largest = {faces, count};
    }
    if (largest.second < 2) return;  // nothing is instanced: the flattened mesh is the file's own
    try {
        checkMeshingMemory(total);
    } catch (const InputError& e) {
        throw InputError(path + ": " + std::to_string(largest.first) + " triangles x " +
                         std::to_string(largest.second) + " instances: " + e.what());
    }
}

// Adds `local` placed by `world`; a mirroring transform reverses the winding (glTF's rule: the
// sign of the world transform's determinant decides which side is the front).
void append(TriangleMesh& out, const TriangleMesh& local, const glm::dmat4& world) {
    const uint32_t base = uint32_t(out.positions.size());
    for (const auto& p : local.positions) out.positions.emplace_back(world * glm::dvec4(p, 1));
    const bool mirror = glm::determinant(glm::dmat3(world)) < 0;
    for (auto t : local.triangles) {
        if (mirror) std::swap(t[1], t[2]);
        out.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    }
}

const char* extension(SceneMeshFormat f) {
    switch (f) {
        case SceneMeshFormat::Gltf: return "gltf";
        case SceneMeshFormat::Glb: return "glb";
        case SceneMeshFormat::Fbx: return "fbx";
        case SceneMeshFormat::Collada: return "dae";
    }
    return "";
}

struct Imported {
    TriangleMesh mesh;
    glm::dvec3 up{0};
    std::vector<std::string> warnings, files;  // files: those read besides the mesh file
};

Imported import(std::string data, const std::string& path, SceneMeshFormat format, const std::string& node) {
    // Named beside the real file, so that the names inside it resolve against its folder.
    const std::string name =
        (std::filesystem::path(path).parent_path() / ".tetglow-mesh.").string() + extension(format);
    Assimp::Importer importer;
    auto* files = new FileSystem(name, std::move(data));
    importer.SetIOHandler(files);  // the importer owns it
    // Only geometry: no textures, materials, animations, cameras or lights; FBX pivots folded
    // into their nodes (else helper nodes stand between a node and its name).
    for (const char* key :
         {AI_CONFIG_IMPORT_FBX_READ_TEXTURES, AI_CONFIG_IMPORT_FBX_READ_MATERIALS, AI_CONFIG_IMPORT_FBX_READ_ANIMATIONS,
          AI_CONFIG_IMPORT_FBX_READ_CAMERAS, AI_CONFIG_IMPORT_FBX_READ_LIGHTS, AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS})
        importer.SetPropertyBool(key, false);
    const aiScene* scene = importer.ReadFile(name, aiProcess_Triangulate);
    if (!scene || !scene->mRootNode) {
        if (!files->problem().empty()) throw InputError(path + ": " + files->problem());
        std::string why = oneLine(importer.GetErrorString());  // names the file by our name for it
        for (size_t at; (at = why.find(name)) != std::string::npos;) why.replace(at, name.size(), path);
        throw InputError(path + ": cannot read the " + extension(format) + " file: " + shorten(why, 200));
    }
    // Without a mesh, Assimp's Collada, FBX and BVH importers build a placeholder skeleton mesh
    // from the nodes and flag the scene incomplete: that skeleton is no geometry of the file.
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
        throw InputError(path + ": no triangles: the file holds no mesh (only cameras, lights or empty nodes)");
    Imported result;
    int32_t upAxis = -1, upSign = 0;
    if (scene->mMetaData && scene->mMetaData->Get("UpAxis", upAxis) && scene->mMetaData->Get("UpAxisSign", upSign) &&
        upAxis >= 0 && upAxis < 3 && (upSign == 1 || upSign == -1))
        result.up[upAxis] = upSign;
    const std::vector<Placed> nodes = placeNodes(scene->mRootNode, path);
    const aiNode* top = node.empty() ? scene->mRootNode : findNode(nodes, node, path);
    BoneWorlds bones;  // only where a mesh has a skin
    for (unsigned i = 0; i < scene->mNumMeshes && bones.empty(); ++i)
        if (scene->mMeshes[i] && scene->mMeshes[i]->mNumBones)
            for (const Placed& p : nodes) bones.emplace(p.node->mName.C_Str(), p.world);
    result.files = files->read();
    TriangleMesh& out = result.mesh;
    size_t skipped = 0, singular = 0;
    checkInstancing(*scene, nodes, top, path);
    // Each set of meshes is read and welded once, however many nodes place it.
    struct Local {
        TriangleMesh mesh;
        size_t skipped = 0;
    };
    std::map<std::vector<unsigned>, Local> locals;
    for (const Placed& p : nodes) {
        if (!p.node->mNumMeshes || !within(p.node, top)) continue;
        const double det = glm::determinant(glm::dmat3(p.world));
        if (!std::isfinite(det))
            throw InputError(path + ": node '" + shorten(p.node->mName.C_Str()) +
                             "' has a transform that is not finite");
        if (det == 0) {
            ++singular;
            continue;
        }
        const std::vector<unsigned> key(p.node->mMeshes, p.node->mMeshes + p.node->mNumMeshes);
        // A skinned mesh is posed by its bones for this node alone; other sets are shared.
        const bool skinned = std::any_of(
            key.begin(), key.end(), [&](unsigned m) { return m < scene->mNumMeshes && scene->mMeshes[m]->mNumBones; });
        Local posed;
        const Local* local = &posed;
        if (skinned) {
            posed.mesh = nodeMesh(*scene, *p.node, p.world, bones, path, posed.skipped);
        } else {
            auto shared = locals.find(key);
            if (shared == locals.end()) {
                Local l;
                l.mesh = nodeMesh(*scene, *p.node, p.world, bones, path, l.skipped);
                shared = locals.emplace(key, std::move(l)).first;
            }
            local = &shared->second;
        }
        skipped += local->skipped;
        if (local->mesh.triangles.size() > kMaxSceneMeshTriangles - out.triangles.size())
            throw InputError(path + ": more than " + std::to_string(kMaxSceneMeshTriangles) +
                             " triangles once every node's meshes are placed");
        const size_t first = out.positions.size();
        append(out, local->mesh, p.world);
        Bounds3 placed;
        for (size_t v = first; v < out.positions.size(); ++v) placed.extend(out.positions[v]);
        if (const std::string problem = precisionProblem(placed); !problem.empty()) {
            const glm::dvec3 t(p.world[3]);
            char transform[160];
            std::snprintf(transform, sizeof transform, "translation (%g, %g, %g), scale %g", t.x, t.y, t.z,
                          std::cbrt(std::abs(det)));
            throw InputError(path + ": node '" + shorten(p.node->mName.C_Str()) + "': its transform (" + transform +
                             ") leaves a mesh that " + problem);
        }
    }
    if (skipped)
        addWarning(result.warnings,
                   path + ": skipped " + std::to_string(skipped) + " points and lines (only triangles bound a medium)");
    if (singular)
        addWarning(result.warnings,
                   path + ": skipped " + std::to_string(singular) + " nodes whose transform flattens them (scale 0)");
    if (out.triangles.empty())
        throw InputError(path + ": no triangles" + (node.empty() ? "" : " in node '" + shorten(node) + "'"));
    return result;
}

// The bytes of the regular files in the model's folder that the file's "uri" members name (a
// glTF's external buffers), by a scan of the text rather than a parse: the JSON is Assimp's to
// parse, in its child. Capped at the mesh limit, which readInputFile enforces on them anyway.
uint64_t externalBytes(const std::string& data, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(path).parent_path();
    uint64_t total = 0;
    for (size_t at = data.find("\"uri\""); at != std::string::npos; at = data.find("\"uri\"", at + 1)) {
        size_t i = data.find_first_not_of(" \t\r\n", at + 5);
        if (i == std::string::npos || data[i] != ':') continue;
        i = data.find_first_not_of(" \t\r\n", i + 1);
        if (i == std::string::npos || data[i] != '"') continue;
        const size_t end = data.find('"', i + 1);
        if (end == std::string::npos) break;
        const std::string written = data.substr(i + 1, end - i - 1);
        const std::string uri = percentDecoded(written).value_or(written);
        const fs::path relative = fs::path(uri).lexically_normal();
        if (uri.starts_with("data:") || relative.is_absolute() || relative.empty() || *relative.begin() == "..")
            continue;
        std::error_code ec;
        const fs::path file = folder / relative;
        if (fs::is_regular_file(file, ec)) total += fs::file_size(file, ec);
        if (total >= kMaxMeshFileBytes) return kMaxMeshFileBytes;
    }
    return total;
}

}  // namespace

ChildLimits sceneImportLimits(const std::string& data, const std::string& path) {
    const double size = double(data.size()) + double(externalBytes(data, path));
    return {std::min(defaultChildMemory(), 2e9 + 100 * size), 10 + 5 * size / 1e6};
}

// Assimp's parsers recurse as deep as a file nests (a glTF's JSON, a node hierarchy), and a
// hostile file can make them allocate or loop without end (a Collada index list that never
// advances): the import runs in a child process under a memory and a time limit, and its
// crash or its limit is an error here. The time grows with the file: a 36 MB GLB of 2 million
// triangles takes 1.5 s a MB on a busy machine (import, placing, welding and the answer), so
// 5 s a MB leaves a wide margin. Memory grows with the file too (that GLB's import peaks at 0.3
// GB, 8 bytes a byte of file): 2 GB and 100 bytes a byte, and a small hostile file that makes
// Assimp allocate without end is stopped there, not at half the machine. A byte is a byte of
// the file or of the external buffers it names (sceneImportLimits): the same mesh as a .gltf
// and its .bin gets the limits it gets as one GLB.
TriangleMesh parseSceneMeshes(std::string data, const std::string& path, SceneMeshFormat format,
                              const std::string& node, std::vector<std::string>* warnings, glm::dvec3* up) {
    const ChildLimits limits = sceneImportLimits(data, path);
    const std::string importer = std::string("the ") + extension(format) + " importer (Assimp)";
    std::string answer;
    try {
        answer = runInChild(
            [&] {
                // Draco data decoded here, in the child too: its decoder runs on the file's bytes.
                if (format == SceneMeshFormat::Gltf || format == SceneMeshFormat::Glb)
                    if (std::optional<std::string> plain = withDracoDecoded(path, data)) data = std::move(*plain);
                Imported r = import(std::move(data), path, format, node);
                ByteWriter m;
                m.addStrings(r.warnings);
                m.addStrings(r.files);
                m.addItems(&r.up, 1);
                addMesh(m, r.mesh);
                return std::move(m.bytes());
            },
            limits);
    } catch (const ChildFailure& e) {
        if (e.kind == ChildFailure::Kind::Signal)
            throw InputError(path + ": " + importer + " crashed on this file (" + e.detail +
                             "), as it does on one nested too deep");
        throw InputError(path + ": " + importer + " " + e.what());
    }
    ByteReader reply(std::move(answer), "the mesh importer");
    for (const auto& w : reply.strings())
        if (warnings) addWarning(*warnings, w);
    for (const auto& f : reply.strings()) noteInputFile(f);
    const auto stated = reply.items<glm::dvec3>();
    if (stated.size() != 1) reply.lost();
    if (up) *up = stated[0];
    return takeMesh(reply);
}

}  // namespace tetglow
