#include "MeshWriters.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <sstream>

namespace tetglow::test {
namespace {

template <class T>
void put(std::string& out, T v, bool little = true) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof v);
    if (little != (std::endian::native == std::endian::little)) std::reverse(b, b + sizeof b);
    out.append(b, sizeof b);
}

std::string plyHeader(const PolygonMesh& m, const std::string& format, const std::string& vertexType,
                      const std::string& faceElement) {
    std::ostringstream s;
    s << "ply\nformat " << format << " 1.0\ncomment written by the tests\nelement vertex " << m.positions.size()
      << "\n";
    for (const char* axis : {"x", "y", "z"}) s << "property " << vertexType << ' ' << axis << "\n";
    s << faceElement << "end_header\n";
    return s.str();
}

// Positions as "x y z" lines, then each polygon as "n v0 v1 ...", as OFF and ASCII PLY have them.
std::string countedFaceLines(const PolygonMesh& m) {
    std::ostringstream s;
    for (const auto& p : m.positions) s << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& f : m.faces) {
        s << f.size();
        for (uint32_t v : f) s << ' ' << v;
        s << '\n';
    }
    return s.str();
}

}  // namespace

TriangleMesh PolygonMesh::fanned() const {
    TriangleMesh t;
    t.positions = positions;
    for (const auto& f : faces) addPolygon(t, f, "");
    return t;
}

PolygonMesh boxQuads() {
    PolygonMesh m;
    for (int i = 0; i < 8; ++i) m.positions.emplace_back(2.0 * (i & 1), 3.0 * (i >> 1 & 1), 4.0 * (i >> 2 & 1));
    m.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return m;
}

std::string objText(const PolygonMesh& m) {
    std::ostringstream s;
    for (const auto& p : m.positions) s << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& f : m.faces) {
        s << 'f';
        for (uint32_t v : f) s << ' ' << v + 1;
        s << '\n';
    }
    return s.str();
}

std::string offText(const PolygonMesh& m) {
    return "OFF\n" + std::to_string(m.positions.size()) + ' ' + std::to_string(m.faces.size()) + " 0\n" +
           countedFaceLines(m);
}

std::string plyAscii(const PolygonMesh& m) {
    return plyHeader(m, "ascii", "float",
                     "element face " + std::to_string(m.faces.size()) + "\nproperty list uchar int vertex_indices\n") +
           countedFaceLines(m);
}

std::string plyBinary(const PolygonMesh& m, bool little) {
    std::string s = plyHeader(m, little ? "binary_little_endian" : "binary_big_endian", "double",
                              "element face " + std::to_string(m.faces.size()) +
                                  "\nproperty uchar flags\nproperty list uchar uint vertex_indices\n");
    for (const auto& p : m.positions)
        for (int k = 0; k < 3; ++k) put<double>(s, p[k], little);
    for (const auto& f : m.faces) {
        put<uint8_t>(s, 7);
        put<uint8_t>(s, uint8_t(f.size()));
        for (uint32_t v : f) put<uint32_t>(s, v, little);
    }
    return s;
}

std::string plyStrips(const PolygonMesh& m) {
    std::ostringstream s;
    s << plyHeader(m, "ascii", "float", "element tristrips 1\nproperty list int int vertex_indices\n");
    for (const auto& p : m.positions) s << p.x << ' ' << p.y << ' ' << p.z << '\n';
    s << 5 * m.faces.size() - 1;
    for (size_t i = 0; i < m.faces.size(); ++i) {
        const auto& f = m.faces[i];
        s << ' ' << f[0] << ' ' << f[1] << ' ' << f[3] << ' ' << f[2] << (i + 1 < m.faces.size() ? " -1" : "");
    }
    return s.str() + "\n";
}

std::string stlAscii(const TriangleMesh& m) {
    std::ostringstream s;
    s << "solid box\n";
    for (uint32_t t = 0; t < m.triangles.size(); ++t) {
        s << "  facet normal 0 0 0\n    outer loop\n";
        for (int k = 0; k < 3; ++k)
            s << "      vertex " << m.corner(t, k).x << ' ' << m.corner(t, k).y << ' ' << m.corner(t, k).z << '\n';
        s << "    endloop\n  endfacet\n";
    }
    return s.str() + "endsolid box\n";
}

std::string stlBinary(const TriangleMesh& m, const std::string& header) {
    std::string s = header.substr(0, 80);
    s.resize(80, ' ');
    put<uint32_t>(s, uint32_t(m.triangles.size()));
    for (uint32_t t = 0; t < m.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) put<float>(s, 0);
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) put<float>(s, float(m.corner(t, k)[a]));
        put<uint16_t>(s, 0);
    }
    return s;
}

Gltf gltf(const std::vector<TriangleMesh>& meshes, const std::vector<GltfNode>& nodes, const std::vector<int>& roots,
          const std::string& binUri) {
    Gltf g;
    std::ostringstream views, accessors, meshList, nodeList;
    for (size_t i = 0; i < meshes.size(); ++i) {
        const TriangleMesh& m = meshes[i];
        const Bounds3 b = bounds(m);
        const size_t positions = g.bin.size();
        for (const auto& p : m.positions)
            for (int k = 0; k < 3; ++k) put<float>(g.bin, float(p[k]));
        const size_t indices = g.bin.size();
        for (const auto& t : m.triangles)
            for (uint32_t v : t) put<uint32_t>(g.bin, v);
        const std::string sep = i ? ", " : "";
        views << sep << "{\"buffer\": 0, \"byteOffset\": " << positions << ", \"byteLength\": " << indices - positions
              << "}, "
              << "{\"buffer\": 0, \"byteOffset\": " << indices << ", \"byteLength\": " << g.bin.size() - indices << "}";
        accessors << sep << "{\"bufferView\": " << 2 * i
                  << ", \"componentType\": 5126, \"count\": " << m.positions.size()
                  << ", \"type\": \"VEC3\", \"min\": [" << b.lo.x << ", " << b.lo.y << ", " << b.lo.z << "], \"max\": ["
                  << b.hi.x << ", " << b.hi.y << ", " << b.hi.z << "]}, "
                  << "{\"bufferView\": " << 2 * i + 1
                  << ", \"componentType\": 5125, \"count\": " << 3 * m.triangles.size() << ", \"type\": \"SCALAR\"}";
        meshList << sep << "{\"name\": \"mesh" << i << "\", \"primitives\": [{\"attributes\": {\"POSITION\": " << 2 * i
                 << "}, \"indices\": " << 2 * i + 1 << "}]}";
    }
    for (size_t i = 0; i < nodes.size(); ++i) {
        const GltfNode& n = nodes[i];
        nodeList << (i ? ", " : "") << "{\"name\": \"" << n.name << "\"";
        if (n.mesh >= 0) nodeList << ", \"mesh\": " << n.mesh;
        if (!n.children.empty()) {
            nodeList << ", \"children\": [";
            for (size_t c = 0; c < n.children.size(); ++c) nodeList << (c ? ", " : "") << n.children[c];
            nodeList << "]";
        }
        if (!n.transform.empty()) nodeList << ", " << n.transform;
        nodeList << "}";
    }
    std::ostringstream rootList;
    for (size_t r = 0; r < roots.size(); ++r) rootList << (r ? ", " : "") << roots[r];
    g.json =
        "{\"asset\": {\"version\": \"2.0\", \"generator\": \"tetglow tests\"}, \"scene\": 0, \"scenes\": [{\"nodes\": "
        "[" +
        rootList.str() + "]}], \"nodes\": [" + nodeList.str() + "], \"meshes\": [" + meshList.str() +
        "], \"accessors\": [" + accessors.str() + "], \"bufferViews\": [" + views.str() + "], \"buffers\": [{" +
        (binUri.empty() ? "" : "\"uri\": \"" + binUri + "\", ") + "\"byteLength\": " + std::to_string(g.bin.size()) +
        "}]}";
    return g;
}

std::string glb(const Gltf& g) {
    std::string json = g.json, bin = g.bin;
    json.resize((json.size() + 3) / 4 * 4, ' ');
    bin.resize((bin.size() + 3) / 4 * 4, '\0');
    std::string s = "glTF";
    put<uint32_t>(s, 2);
    put<uint32_t>(s, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    put<uint32_t>(s, uint32_t(json.size()));
    s += "JSON" + json;
    put<uint32_t>(s, uint32_t(bin.size()));
    s += std::string("BIN\0", 4) + bin;
    return s;
}

std::string collada(const TriangleMesh& m, const std::string& upAxis) {
    PolygonMesh polygons;
    polygons.positions = m.positions;
    for (const auto& t : m.triangles) polygons.faces.push_back({t[0], t[1], t[2]});
    return collada(polygons, upAxis);
}

std::string collada(const PolygonMesh& m, const std::string& upAxis, const std::string& bindShape) {
    const std::string identity = "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1";
    std::ostringstream s;
    s << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      << "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
      << "  <asset><unit name=\"meter\" meter=\"1\"/><up_axis>" << upAxis << "</up_axis></asset>\n"
      << "  <library_geometries><geometry id=\"box-mesh\" name=\"box\"><mesh>\n"
      << "    <source id=\"box-positions\"><float_array id=\"box-positions-array\" count=\"" << 3 * m.positions.size()
      << "\">";
    for (const auto& p : m.positions) s << p.x << ' ' << p.y << ' ' << p.z << ' ';
    s << "</float_array>\n      <technique_common><accessor source=\"#box-positions-array\" count=\""
      << m.positions.size()
      << "\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" "
         "type=\"float\"/>"
      << "</accessor></technique_common></source>\n"
      << "    <vertices id=\"box-vertices\"><input semantic=\"POSITION\" source=\"#box-positions\"/></vertices>\n"
      << "    <polylist count=\"" << m.faces.size()
      << "\"><input semantic=\"VERTEX\" source=\"#box-vertices\" offset=\"0\"/><vcount>";
    for (const auto& f : m.faces) s << f.size() << ' ';
    s << "</vcount><p>";
    for (const auto& f : m.faces)
        for (uint32_t v : f) s << v << ' ';
    s << "</p></polylist>\n  </mesh></geometry></library_geometries>\n";
    if (!bindShape.empty()) {
        // One joint at the origin, bound where it stands, every vertex wholly its own.
        s << "  <library_controllers><controller id=\"box-skin\"><skin source=\"#box-mesh\">"
          << "<bind_shape_matrix>" << bindShape << "</bind_shape_matrix>\n"
          << "    <source id=\"joints\"><Name_array id=\"joints-array\" count=\"1\">Bone</Name_array>"
          << "<technique_common><accessor source=\"#joints-array\" count=\"1\" stride=\"1\"><param name=\"JOINT\" "
             "type=\"name\"/></accessor></technique_common></source>\n"
          << "    <source id=\"binds\"><float_array id=\"binds-array\" count=\"16\">" << identity
          << "</float_array><technique_common><accessor source=\"#binds-array\" count=\"1\" stride=\"16\"><param "
             "name=\"TRANSFORM\" type=\"float4x4\"/></accessor></technique_common></source>\n"
          << "    <source id=\"weights\"><float_array id=\"weights-array\" count=\"1\">1</float_array>"
          << "<technique_common><accessor source=\"#weights-array\" count=\"1\" stride=\"1\"><param name=\"WEIGHT\" "
             "type=\"float\"/></accessor></technique_common></source>\n"
          << "    <joints><input semantic=\"JOINT\" source=\"#joints\"/><input semantic=\"INV_BIND_MATRIX\" "
             "source=\"#binds\"/></joints>\n"
          << "    <vertex_weights count=\"" << m.positions.size()
          << "\"><input semantic=\"JOINT\" source=\"#joints\" offset=\"0\"/><input semantic=\"WEIGHT\" "
             "source=\"#weights\" offset=\"1\"/><vcount>";
        for (size_t i = 0; i < m.positions.size(); ++i) s << "1 ";
        s << "</vcount><v>";
        for (size_t i = 0; i < m.positions.size(); ++i) s << "0 0 ";
        s << "</v></vertex_weights>\n  </skin></controller></library_controllers>\n";
    }
    s << "  <library_visual_scenes><visual_scene id=\"Scene\" name=\"Scene\">\n";
    if (bindShape.empty())
        s << "    <node id=\"Box\" name=\"Box\" type=\"NODE\"><matrix sid=\"transform\">" << identity << "</matrix>"
          << "<instance_geometry url=\"#box-mesh\" name=\"Box\"/></node>\n";
    else
        s << "    <node id=\"Bone\" sid=\"Bone\" name=\"Bone\" type=\"JOINT\"><matrix sid=\"transform\">" << identity
          << "</matrix></node>\n"
          << "    <node id=\"Box\" name=\"Box\" type=\"NODE\"><matrix sid=\"transform\">" << identity << "</matrix>"
          << "<instance_controller url=\"#box-skin\"><skeleton>#Bone</skeleton></instance_controller></node>\n";
    s << "  </visual_scene></library_visual_scenes>\n"
      << "  <scene><instance_visual_scene url=\"#Scene\"/></scene>\n</COLLADA>\n";
    return s.str();
}

std::string fbxAscii(const PolygonMesh& m) {
    std::ostringstream s;
    s << "; FBX 7.4.0 project file\n"
      << "FBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n\tFBXVersion: 7400\n}\n"
      << "GlobalSettings:  {\n\tVersion: 1000\n\tProperties70:  {\n"
      << "\t\tP: \"UpAxis\", \"int\", \"Integer\", \"\",1\n\t\tP: \"UnitScaleFactor\", \"double\", \"Number\", "
         "\"\",1\n\t}\n}\n"
      << "Objects:  {\n\tGeometry: 1000, \"Geometry::Box\", \"Mesh\" {\n\t\tVertices: *" << 3 * m.positions.size()
      << " {\n\t\t\ta: ";
    for (size_t i = 0; i < m.positions.size(); ++i)
        s << (i ? "," : "") << m.positions[i].x << ',' << m.positions[i].y << ',' << m.positions[i].z;
    size_t corners = 0;
    for (const auto& f : m.faces) corners += f.size();
    s << "\n\t\t}\n\t\tPolygonVertexIndex: *" << corners << " {\n\t\t\ta: ";
    bool first = true;
    for (const auto& f : m.faces)
        for (size_t k = 0; k < f.size(); ++k) {
            // The last corner of each polygon is stored as -(index + 1).
            s << (first ? "" : ",") << (k + 1 == f.size() ? -int64_t(f[k]) - 1 : int64_t(f[k]));
            first = false;
        }
    s << "\n\t\t}\n\t\tGeometryVersion: 124\n\t}\n"
      << "\tModel: 2000, \"Model::Box\", \"Mesh\" {\n\t\tVersion: 232\n\t\tProperties70:  {\n\t\t}\n\t\tShading: "
         "T\n\t\tCulling: \"CullingOff\"\n\t}\n}\n"
      << "Connections:  {\n\tC: \"OO\",2000,0\n\tC: \"OO\",1000,2000\n}\n";
    return s.str();
}

}  // namespace tetglow::test
