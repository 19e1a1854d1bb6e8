#include "scene/AssimpReader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "base/InputFile.h"
#include "scene/MeshWeld.h"

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
    FileSystem(const std::string& mainName, std::string data) : total_(data.size()) { files_[mainName] = std::move(data); }
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
                std::string data = readInputFile(name, kMaxMeshFileBytes - std::min(kMaxMeshFileBytes, total_), "the rest of a mesh's files (1024 MiB in all)");
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
        if (nodes.size() > kMaxSceneMeshTriangles) throw InputError(path + ": more than " + std::to_string(kMaxSceneMeshTriangles) + " nodes");
        for (unsigned c = p.node->mNumChildren; c-- > 0;)  // the first child on top: the file's order
            if (const aiNode* child = p.node->mChildren[c]) stack.push_back({child, p.world * toGlm(child->mTransformation)});
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
        if (p.node->mNumMeshes && named.size() < 200) named += std::string(named.empty() ? "" : ", ") + "'" + p.node->mName.C_Str() + "'";
    }
    if (count > 1) throw InputError(path + ": " + std::to_string(count) + " nodes are named '" + shorten(name) + "'");
    if (!found)
        throw InputError(path + ": no node named '" + shorten(name) + "' (nodes with meshes: " + (named.empty() ? "none" : shorten(named, 200)) + ")");
    return found;
}

// The triangles of the node's meshes in the node's own coordinates; counts other faces in `skipped`.
TriangleMesh nodeMesh(const aiScene& scene, const aiNode& node, const std::string& path, size_t& skipped) {
    TriangleMesh local;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        if (node.mMeshes[i] >= scene.mNumMeshes) throw InputError(path + ": a node names mesh " + std::to_string(node.mMeshes[i]) + " of " + std::to_string(scene.mNumMeshes));
        const aiMesh& m = *scene.mMeshes[node.mMeshes[i]];
        const uint32_t base = uint32_t(local.positions.size());
        for (unsigned v = 0; v < m.mNumVertices; ++v) local.positions.emplace_back(m.mVertices[v].x, m.mVertices[v].y, m.mVertices[v].z);
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) {
                ++skipped;
                continue;
            }
            for (unsigned k = 0; k < 3; ++k)
                if (face.mIndices[k] >= m.mNumVertices)
                    throw InputError(path + ": mesh '" + shorten(m.mName.C_Str()) + "': face " + std::to_string(f) + ": vertex index " +
                                     std::to_string(face.mIndices[k]) + " out of range (" + std::to_string(m.mNumVertices) + " vertices)");
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
    const std::string name = (std::filesystem::path(path).parent_path() / ".tetglow-mesh.").string() + extension(format);
    Assimp::Importer importer;
    auto* files = new FileSystem(name, std::move(data));
    importer.SetIOHandler(files);  // the importer owns it
    // Only geometry: no textures, materials, animations, cameras or lights; FBX pivots folded
    // into their nodes (else helper nodes stand between a node and its name).
    for (const char* key : {AI_CONFIG_IMPORT_FBX_READ_TEXTURES, AI_CONFIG_IMPORT_FBX_READ_MATERIALS, AI_CONFIG_IMPORT_FBX_READ_ANIMATIONS,
                            AI_CONFIG_IMPORT_FBX_READ_CAMERAS, AI_CONFIG_IMPORT_FBX_READ_LIGHTS, AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS})
        importer.SetPropertyBool(key, false);
    const aiScene* scene = importer.ReadFile(name, aiProcess_Triangulate);
    if (!scene || !scene->mRootNode) {
        if (!files->problem().empty()) throw InputError(path + ": " + files->problem());
        std::string why = oneLine(importer.GetErrorString());  // names the file by our name for it
        for (size_t at; (at = why.find(name)) != std::string::npos;) why.replace(at, name.size(), path);
        throw InputError(path + ": cannot read the " + extension(format) + " file: " + shorten(why, 200));
    }
    const std::vector<Placed> nodes = placeNodes(scene->mRootNode, path);
    const aiNode* top = node.empty() ? scene->mRootNode : findNode(nodes, node, path);
    Imported result;
    result.files = files->read();
    TriangleMesh& out = result.mesh;
    size_t skipped = 0, singular = 0;
    for (const Placed& p : nodes) {
        if (!p.node->mNumMeshes || !within(p.node, top)) continue;
        const double det = glm::determinant(glm::dmat3(p.world));
        if (!std::isfinite(det)) throw InputError(path + ": node '" + shorten(p.node->mName.C_Str()) + "' has a transform that is not finite");
        if (det == 0) {
            ++singular;
            continue;
        }
        TriangleMesh local = nodeMesh(*scene, *p.node, path, skipped);
        if (local.triangles.size() > kMaxSceneMeshTriangles - out.triangles.size())
            throw InputError(path + ": more than " + std::to_string(kMaxSceneMeshTriangles) + " triangles once every node's meshes are placed");
        append(out, std::move(local), p.world);
    }
    if (skipped) addWarning(result.warnings, path + ": skipped " + std::to_string(skipped) + " points and lines (only triangles bound a medium)");
    if (singular) addWarning(result.warnings, path + ": skipped " + std::to_string(singular) + " nodes whose transform flattens them (scale 0)");
    if (out.triangles.empty()) throw InputError(path + ": no triangles" + (node.empty() ? "" : " in node '" + shorten(node) + "'"));
    return result;
}


// What the child process hands back: a flag, then the error, or the warnings, the files read and
// the mesh, each as a count followed by its items.
class Message {
public:
    void add(const void* p, size_t n) { bytes_.append(static_cast<const char*>(p), n); }
    void add(uint64_t n) { add(&n, sizeof n); }
    void add(const std::string& s) { add(s.size()); add(s.data(), s.size()); }
    template <class T>
    void add(const std::vector<T>& items) {
        add(items.size());
        add(items.data(), items.size() * sizeof(T));
    }
    void addStrings(const std::vector<std::string>& items) {
        add(items.size());
        for (const auto& s : items) add(s);
    }
    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
};

class Reply {
public:
    explicit Reply(std::string bytes) : bytes_(std::move(bytes)) {}
    void take(void* p, size_t n) {
        if (n > bytes_.size() - pos_) throw std::runtime_error("lost the mesh importer's reply");
        std::memcpy(p, bytes_.data() + pos_, n);
        pos_ += n;
    }
    uint64_t count(size_t itemBytes) {
        uint64_t n;
        take(&n, sizeof n);
        if (n > (bytes_.size() - pos_) / itemBytes) throw std::runtime_error("lost the mesh importer's reply");
        return n;
    }
    std::string string() {
        std::string s(count(1), '\0');
        take(s.data(), s.size());
        return s;
    }
    template <class T>
    std::vector<T> items() {
        std::vector<T> v(count(sizeof(T)));
        take(v.data(), v.size() * sizeof(T));
        return v;
    }
    std::vector<std::string> strings() {
        std::vector<std::string> v(count(sizeof(uint64_t)));
        for (auto& s : v) s = string();
        return v;
    }

private:
    std::string bytes_;
    size_t pos_ = 0;
};

void writeAll(int fd, const std::string& bytes) {
    for (size_t done = 0; done < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += size_t(n);
    }
}

std::string readAll(int fd) {
    std::string bytes;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return bytes;
        bytes.append(buffer, size_t(n));
    }
}

}  // namespace

// Assimp's parsers recurse as deep as a file nests (a glTF's JSON, a node hierarchy), so a
// hostile file can overflow the stack: the import runs in a child process, as TetGen does, and
// a crash there is an error here.
TriangleMesh parseSceneMeshes(std::string data, const std::string& path, SceneMeshFormat format, const std::string& node,
                              std::vector<std::string>* warnings) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("cannot create a pipe for the mesh importer");
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot fork a process for the mesh importer");
    if (pid == 0) {
        ::close(fds[0]);
        Message m;
        try {
            Imported r = import(std::move(data), path, format, node);
            m.add(uint64_t(1));
            m.addStrings(r.warnings);
            m.addStrings(r.files);
            m.add(r.mesh.positions);
            m.add(r.mesh.triangles);
        } catch (const std::exception& e) {
            m = Message();
            m.add(uint64_t(0));
            m.add(dynamic_cast<const InputError*>(&e) ? std::string(e.what()) : path + ": " + e.what());
        }
        writeAll(fds[1], m.bytes());
        ::_exit(0);
    }
    ::close(fds[1]);
    std::string bytes = readAll(fds[0]);
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status))
        throw InputError(path + ": the " + extension(format) + " importer (Assimp) crashed on this file (" + strsignal(WTERMSIG(status)) +
                         "), as it does on one nested too deep");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw InputError(path + ": the " + extension(format) + " importer (Assimp) failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")");
    Reply reply(std::move(bytes));
    uint64_t ok;
    reply.take(&ok, sizeof ok);
    if (!ok) throw InputError(reply.string());
    for (const auto& w : reply.strings())
        if (warnings) addWarning(*warnings, w);
    for (const auto& f : reply.strings()) noteInputFile(f);
    TriangleMesh mesh;
    mesh.positions = reply.items<glm::dvec3>();
    mesh.triangles = reply.items<std::array<uint32_t, 3>>();
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t)
            if (v >= mesh.positions.size()) throw std::runtime_error("lost the mesh importer's reply");
    return mesh;
}

}  // namespace tetglow
