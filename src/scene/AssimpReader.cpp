#include "scene/AssimpReader.h"

#include <algorithm>
#include <cmath>
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
#include "base/InputFile.h"
#include "scene/MeshWeld.h"
#include "tet/MeshMessage.h"

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
// extension picks the importer) and, read on demand through readInputFile, the files it names.
// Opening fails (and the first reason is kept) for anything readInputFile refuses, for writing,
// and once all files together exceed the mesh limit.
class FileSystem : public Assimp::IOSystem {
public:
    FileSystem(const std::string& mainName, std::string data) : total_(data.size()) {
        files_[mainName] = std::move(data);
    }
    bool Exists(const char* name) const override {
        std::error_code ec;
        return files_.count(name) || std::filesystem::exists(name, ec);
    }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* name, const char* mode) override {
        if (std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+')) return nullptr;
        auto it = files_.find(name);
        if (it == files_.end()) {
            try {
                std::string data = readInputFile(name, kMaxMeshFileBytes - std::min(kMaxMeshFileBytes, total_),
                                                 "the rest of a mesh's files (1024 MiB in all)");
                total_ += data.size();
                read_.push_back(name);
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

// The triangles of the node's meshes in the node's own coordinates; counts other faces in `skipped`.
TriangleMesh nodeMesh(const aiScene& scene, const aiNode& node, const std::string& path, size_t& skipped) {
    TriangleMesh local;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        if (node.mMeshes[i] >= scene.mNumMeshes)
            throw InputError(path + ": a node names mesh " + std::to_string(node.mMeshes[i]) + " of " +
                             std::to_string(scene.mNumMeshes));
        const aiMesh& m = *scene.mMeshes[node.mMeshes[i]];
        const uint32_t base = uint32_t(local.positions.size());
        for (unsigned v = 0; v < m.mNumVertices; ++v)
            local.positions.emplace_back(m.mVertices[v].x, m.mVertices[v].y, m.mVertices[v].z);
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

// Adds `local` placed by `world`; a mirroring transform reverses the winding (glTF's rule: the
// sign of the world transform's determinant decides which side is the front).
void append(TriangleMesh& out, TriangleMesh local, const glm::dmat4& world) {
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
    const std::vector<Placed> nodes = placeNodes(scene->mRootNode, path);
    const aiNode* top = node.empty() ? scene->mRootNode : findNode(nodes, node, path);
    Imported result;
    result.files = files->read();
    TriangleMesh& out = result.mesh;
    size_t skipped = 0, singular = 0;
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
        TriangleMesh local = nodeMesh(*scene, *p.node, path, skipped);
        if (local.triangles.size() > kMaxSceneMeshTriangles - out.triangles.size())
            throw InputError(path + ": more than " + std::to_string(kMaxSceneMeshTriangles) +
                             " triangles once every node's meshes are placed");
        append(out, std::move(local), p.world);
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

}  // namespace

// Assimp's parsers recurse as deep as a file nests (a glTF's JSON, a node hierarchy), and a
// hostile file can make them allocate or loop without end (a Collada index list that never
// advances): the import runs in a child process under a memory and a time limit, and its
// crash or its limit is an error here. The time grows with the file: a 36 MB GLB of 2 million
// triangles takes 1.5 s a MB on a busy machine (import, placing, welding and the answer), and
// a file's buffers read in the child are not counted, so 5 s a MB leaves a wide margin. Memory
// grows with the file too (that GLB's import peaks at 0.3 GB, 8 bytes a byte of file): 2 GB
// and 100 bytes a byte leave room for external buffers, and a small hostile file that makes
// Assimp allocate without end is stopped there, not at half the machine.
TriangleMesh parseSceneMeshes(std::string data, const std::string& path, SceneMeshFormat format,
                              const std::string& node, std::vector<std::string>* warnings) {
    const double size = double(data.size());
    const ChildLimits limits{std::min(defaultChildMemory(), 2e9 + 100 * size), 10 + 5 * size / 1e6};
    const std::string importer = std::string("the ") + extension(format) + " importer (Assimp)";
    std::string answer;
    try {
        answer = runInChild(
            [&] {
                Imported r = import(std::move(data), path, format, node);
                ByteWriter m;
                m.addStrings(r.warnings);
                m.addStrings(r.files);
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
    return takeMesh(reply);
}

}  // namespace tetglow
