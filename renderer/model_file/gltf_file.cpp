#include "model_file/gltf_file.h"

#include "model_file/model_limits.h"

#include <fstream>  // tinygltf's writer needs it even without file access of its own

#define TINYGLTF_IMPLEMENTATION  // compiled here, from Debian's header, for the desktop and the browser alike
#define TINYGLTF_NO_STB_IMAGE        // no image is ever decoded (textures are ignored)
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE   // nor an image file opened
#define TINYGLTF_NO_FS               // every file through FsCallbacks below
#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>
#include <map>
#include <set>

namespace m3055::model_file {

namespace {

// Extensions that change what the geometry is (compressed, quantized or
// instanced): a file that requires one cannot be read as plain triangles.
bool changes_geometry(const std::string& name) {
    return name == "KHR_draco_mesh_compression" || name == "EXT_meshopt_compression" ||
           name == "KHR_mesh_quantization" || name == "EXT_mesh_gpu_instancing";
}

// Only materials' and textures' extensions may be required: they are ignored.
bool ignorable(const std::string& name) {
    for (const char* prefix : {"KHR_materials_", "KHR_texture_", "EXT_texture_"})
        if (name.rfind(prefix, 0) == 0) return true;
    return false;
}

// The deepest nesting of arrays and objects in JSON text, strings skipped:
// tinygltf reads "extras" recursively, so a deep file is refused first.
int json_depth(const char* text, std::size_t size) {
    int depth = 0, deepest = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < size; ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
            continue;
        }
        if (c == '"') in_string = true;
        else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
        else if (c == ']' || c == '}') --depth;
    }
    return deepest;
}

// The JSON chunk of a .glb (its header: magic, version, length; then the
// chunk's length and type), or nothing when it is not one.
bool glb_json(const std::string& bytes, const char** text, std::size_t* size) {
    if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0) return false;
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    if (length > bytes.size() - 20) return false;
    *text = bytes.data() + 20, *size = length;
    return true;
}

// The types glTF 2.0's schema gives its properties, by the property's name
// (where one name has two meanings, both are allowed): tinygltf skips a
// property of the wrong type and goes on with its default, so a broken file
// would load as something else. Inside "extras" (anything) and an
// extension's object (its own schema) nothing is checked.
enum class Want { string, uint, number, number_or_numbers, numbers, uints, object, objects, strings, uint_object };

const std::map<std::string, Want>& property_types() {
    static const std::map<std::string, Want> types = {
        {"name", Want::string}, {"uri", Want::string}, {"mimeType", Want::string}, {"type", Want::string},
        {"generator", Want::string}, {"version", Want::string}, {"minVersion", Want::string},
        {"copyright", Want::string}, {"alphaMode", Want::string}, {"interpolation", Want::string},
        {"path", Want::string},
        {"index", Want::uint}, {"texCoord", Want::uint}, {"bufferView", Want::uint}, {"buffer", Want::uint},
        {"byteOffset", Want::uint}, {"byteLength", Want::uint}, {"byteStride", Want::uint}, {"count", Want::uint},
        {"componentType", Want::uint}, {"mode", Want::uint}, {"indices", Want::uint}, {"material", Want::uint},
        {"mesh", Want::uint}, {"camera", Want::uint}, {"skin", Want::uint}, {"scene", Want::uint},
        {"sampler", Want::uint}, {"source", Want::uint}, {"magFilter", Want::uint}, {"minFilter", Want::uint},
        {"wrapS", Want::uint}, {"wrapT", Want::uint}, {"input", Want::uint}, {"output", Want::uint},
        {"node", Want::uint}, {"skeleton", Want::uint}, {"inverseBindMatrices", Want::uint},
        {"strength", Want::number}, {"alphaCutoff", Want::number}, {"metallicFactor", Want::number},
        {"roughnessFactor", Want::number}, {"yfov", Want::number}, {"znear", Want::number}, {"zfar", Want::number},
        {"aspectRatio", Want::number}, {"xmag", Want::number}, {"ymag", Want::number},
        {"scale", Want::number_or_numbers},  // a texture's number, a node's three
        {"matrix", Want::numbers}, {"translation", Want::numbers}, {"rotation", Want::numbers},
        {"weights", Want::numbers}, {"baseColorFactor", Want::numbers}, {"emissiveFactor", Want::numbers},
        {"min", Want::numbers}, {"max", Want::numbers},
        {"children", Want::uints}, {"nodes", Want::uints}, {"joints", Want::uints},
        {"asset", Want::object}, {"pbrMetallicRoughness", Want::object}, {"normalTexture", Want::object},
        {"occlusionTexture", Want::object}, {"emissiveTexture", Want::object}, {"baseColorTexture", Want::object},
        {"metallicRoughnessTexture", Want::object}, {"sparse", Want::object}, {"values", Want::object},
        {"orthographic", Want::object}, {"perspective", Want::object},
        {"accessors", Want::objects}, {"bufferViews", Want::objects}, {"buffers", Want::objects},
        {"materials", Want::objects}, {"meshes", Want::objects}, {"scenes", Want::objects},
        {"images", Want::objects}, {"textures", Want::objects}, {"samplers", Want::objects},
        {"cameras", Want::objects}, {"skins", Want::objects}, {"animations", Want::objects},
        {"primitives", Want::objects}, {"channels", Want::objects},
        {"targets", Want::objects}, {"extensionsUsed", Want::strings}, {"extensionsRequired", Want::strings},
        {"attributes", Want::uint_object},
    };
    return types;
}

bool is_uint(const nlohmann::json& v) { return v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0); }
bool all_of(const nlohmann::json& v, bool (*test)(const nlohmann::json&)) {
    if (!v.is_array()) return false;
    for (const nlohmann::json& e : v)
        if (!test(e)) return false;
    return true;
}

const char* type_problem(const nlohmann::json& v, Want want) {
    auto number = [](const nlohmann::json& e) { return e.is_number(); };
    auto object = [](const nlohmann::json& e) { return e.is_object(); };
    auto string = [](const nlohmann::json& e) { return e.is_string(); };
    switch (want) {
        case Want::string: return v.is_string() ? nullptr : "must be a string";
        case Want::uint: return is_uint(v) ? nullptr : "must be a whole number >= 0";
        case Want::number: return v.is_number() ? nullptr : "must be a number";
        case Want::number_or_numbers: return v.is_number() || all_of(v, number) ? nullptr : "must be a number or numbers";
        case Want::numbers: return all_of(v, number) ? nullptr : "must be an array of numbers";
        case Want::uints: return all_of(v, is_uint) ? nullptr : "must be an array of whole numbers >= 0";
        case Want::object: return v.is_object() ? nullptr : "must be an object";
        case Want::objects: return all_of(v, object) ? nullptr : "must be an array of objects";
        case Want::strings: return all_of(v, string) ? nullptr : "must be an array of strings";
        case Want::uint_object:
            if (!v.is_object()) return "must be an object";
            for (const auto& [key, value] : v.items())
                if (!is_uint(value)) return "must map names to accessor numbers";
            return nullptr;
    }
    return nullptr;
}

// The first property of the wrong type, as "PATH: PROBLEM" (PATH of the
// schema's own names and indices, nothing of the file's values), or "".
std::string first_type_problem(const nlohmann::json& v, const std::string& path) {
    if (v.is_array()) {
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string found = first_type_problem(v[i], path + "[" + std::to_string(i) + "]");
            if (!found.empty()) return found;
        }
        return {};
    }
    if (!v.is_object()) return {};
    for (const auto& [key, value] : v.items()) {
        if (key == "extras") continue;
        if (key == "extensions") {
            if (!value.is_object()) return path + (path.empty() ? "" : ".") + "extensions: must be an object";
            for (const auto& [name, extension] : value.items())
                if (!extension.is_object())
                    return path + (path.empty() ? "" : ".") + "extensions: each extension must be an object";
            continue;
        }
        const auto type = property_types().find(key);
        if (type == property_types().end()) continue;  // not the schema's (an exporter's own key): ignored
        const std::string here = path + (path.empty() ? "" : ".") + key;
        // "nodes": the file's nodes at the top, a scene's node numbers elsewhere.
        const Want want = path.empty() && key == "nodes" ? Want::objects : type->second;
        if (const char* problem = type_problem(value, want)) return here + ": " + problem;
        const std::string found = first_type_problem(value, here);
        if (!found.empty()) return found;
    }
    return {};
}

struct Files {
    const SideFileReader* read;
    std::string problem;  // the reader's, kept: tinygltf's own words would name the path differently
};

bool file_exists(const std::string&, void*) { return true; }  // the read says why not
std::string expand_path(const std::string& path, void*) { return path; }
bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    Files& files = *static_cast<Files*>(user);
    try {
        const std::string bytes = (*files.read)(path);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const ModelError& e) {
        if (files.problem.empty()) files.problem = e.what();
        if (err) *err += "side file refused\n";
        return false;
    }
}
bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "no writes\n";
    return false;
}
// Images are never decoded (textures are ignored): tinygltf is told they loaded.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

// One line of tinygltf's error text, printable and short: its messages name
// fields, but an invalid JSON's may hold a piece of the file, which is cut.
std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    if (line.find("JSON") != std::string::npos || line.find("json") != std::string::npos)
        return "invalid JSON";
    for (char& c : line)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
    if (line.size() > 120) line = line.substr(0, 117) + "...";
    return line;
}

class Reader {
public:
    Reader(const tinygltf::Model& model, Soup& soup, std::size_t max_triangles)
        : model_(model), soup_(soup), max_triangles_(max_triangles) {}

    void read() {
        for (const std::string& name : model_.extensionsRequired) {
            if (changes_geometry(name) || !ignorable(name))
                throw ModelError("requires the extension " + printable(name) +
                                 ", which this program does not read (export without it)");
        }
        std::vector<int> roots;
        const int scene = model_.defaultScene >= 0 ? model_.defaultScene : model_.scenes.empty() ? -1 : 0;
        if (scene >= int(model_.scenes.size())) throw ModelError("names scene " + std::to_string(scene) + ", which it does not have");
        if (scene >= 0) {
            roots = model_.scenes[std::size_t(scene)].nodes;
        } else {
            // No scene: every node no other node holds.
            std::vector<bool> child(model_.nodes.size(), false);
            for (const tinygltf::Node& node : model_.nodes)
                for (int c : node.children)
                    if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
            for (std::size_t i = 0; i < child.size(); ++i)
                if (!child[i]) roots.push_back(int(i));
        }
        std::vector<bool> open(model_.nodes.size(), false);
        for (int root : roots) visit(root, glm::dmat4(1.0), 0, open);
        if (!model_.textures.empty() || !model_.images.empty())
            soup_.notes.push_back("its textures are ignored: each material's factors are used");
    }

    bool lines_or_points = false;

private:
    static std::string printable(const std::string& name) {
        std::string out = "\"";
        for (char c : name.substr(0, 60))
            out += static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F || c == '"' ? '?' : c;
        return out + "\"";
    }

    void visit(int index, const glm::dmat4& parent, int depth, std::vector<bool>& open) {
        if (index < 0 || std::size_t(index) >= model_.nodes.size())
            throw ModelError("names node " + std::to_string(index) + ", which it does not have");
        if (open[std::size_t(index)]) throw ModelError("node " + std::to_string(index) + " holds itself (a cycle)");
        if (depth > kMaxNodeDepth)
            throw ModelError("has nodes nested deeper than " + std::to_string(kMaxNodeDepth) + " levels");
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const glm::dmat4 transform = parent * local_transform(node, index);
        open[std::size_t(index)] = true;
        if (node.mesh >= 0) {
            if (std::size_t(node.mesh) >= model_.meshes.size())
                throw ModelError("node " + std::to_string(index) + " names mesh " + std::to_string(node.mesh) +
                                 ", which the file does not have");
            for (const tinygltf::Primitive& primitive : model_.meshes[std::size_t(node.mesh)].primitives)
                add_primitive(primitive, transform);
        } else if (node.mesh < -1) {
            throw ModelError("node " + std::to_string(index) + " names a negative mesh");
        }
        for (int child : node.children) visit(child, transform, depth + 1, open);
        open[std::size_t(index)] = false;
    }

    static glm::dmat4 local_transform(const tinygltf::Node& node, int index) {
        auto check = [&](const std::vector<double>& values, std::size_t size, const char* what) {
            if (!values.empty() && values.size() != size)
                throw ModelError("node " + std::to_string(index) + "'s " + what + " must have " + std::to_string(size) +
                                 " numbers");
            for (double v : values)
                if (!std::isfinite(v)) throw ModelError("node " + std::to_string(index) + "'s " + what + " is not finite");
        };
        check(node.matrix, 16, "matrix");
        check(node.translation, 3, "translation");
        check(node.rotation, 4, "rotation");
        check(node.scale, 3, "scale");
        if (!node.matrix.empty()) {
            glm::dmat4 m;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[std::size_t(4 * c + r)];  // column-major, as glTF
            return m;
        }
        glm::dmat4 m(1.0);
        if (!node.translation.empty())
            m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
        if (!node.rotation.empty()) {
            glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // glTF: x, y, z, w
            const double length = glm::length(q);
            if (!(length > 0)) throw ModelError("node " + std::to_string(index) + "'s rotation is zero");
            m = m * glm::dmat4(glm::mat3_cast(q / length));
        }
        if (!node.scale.empty())
            m = m * glm::dmat4(glm::dmat3(glm::dvec3(node.scale[0], 0, 0), glm::dvec3(0, node.scale[1], 0),
                                          glm::dvec3(0, 0, node.scale[2])));
        return m;
    }

    // The bytes of accessor `index`, checked against its view and buffer:
    // element i of `size` bytes at data + i * stride.
    struct Span {
        const unsigned char* data;
        std::size_t count, stride;
        int component;
    };
    Span span(int index, int type, const char* what) const {
        if (index < 0 || std::size_t(index) >= model_.accessors.size())
            throw ModelError(std::string(what) + " names accessor " + std::to_string(index) + ", which the file does not have");
        const tinygltf::Accessor& a = model_.accessors[std::size_t(index)];
        const std::string name = "accessor " + std::to_string(index) + " (" + what + ")";
        if (a.sparse.isSparse) throw ModelError(name + " is sparse, which this program does not read");
        if (a.type != type) throw ModelError(name + " has the wrong type");
        if (a.bufferView < 0 || std::size_t(a.bufferView) >= model_.bufferViews.size())
            throw ModelError(name + " has no buffer view");
        const tinygltf::BufferView& view = model_.bufferViews[std::size_t(a.bufferView)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size())
            throw ModelError(name + "'s buffer view names no buffer");
        const std::vector<unsigned char>& buffer = model_.buffers[std::size_t(view.buffer)].data;
        const int components = type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
        const int bytes = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
        if (bytes <= 0) throw ModelError(name + " has an unknown component type");
        const std::size_t element = std::size_t(bytes) * std::size_t(components);
        const std::size_t stride = view.byteStride ? view.byteStride : element;
        if (stride < element) throw ModelError(name + "'s stride is smaller than its elements");
        // Every element inside the view, the view inside the buffer (no overflow: all below 2^40).
        if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
            throw ModelError(name + "'s buffer view reaches past its buffer");
        if (a.count == 0) return {nullptr, 0, stride, a.componentType};
        if (a.byteOffset > view.byteLength || a.count > view.byteLength ||
            (a.count - 1) * stride + element > view.byteLength - a.byteOffset)
            throw ModelError(name + " reaches past its buffer view");
        return {buffer.data() + view.byteOffset + a.byteOffset, a.count, stride, a.componentType};
    }

    std::vector<dvec3> vectors(int index, const char* what) const {
        const Span s = span(index, TINYGLTF_TYPE_VEC3, what);
        if (s.component != TINYGLTF_COMPONENT_TYPE_FLOAT)
            throw ModelError(std::string("the ") + what + " are not floats (a quantized file: export without it)");
        std::vector<dvec3> out(s.count);
        for (std::size_t i = 0; i < s.count; ++i) {
            float v[3];
            std::memcpy(v, s.data + i * s.stride, sizeof v);
            out[i] = {v[0], v[1], v[2]};
        }
        return out;
    }

    std::vector<std::uint32_t> indices(int index, std::size_t vertices) const {
        const Span s = span(index, TINYGLTF_TYPE_SCALAR, "indices");
        std::vector<std::uint32_t> out(s.count);
        for (std::size_t i = 0; i < s.count; ++i) {
            const unsigned char* p = s.data + i * s.stride;
            std::uint32_t v = 0;
            if (s.component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) v = *p;
            else if (s.component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) { std::uint16_t w; std::memcpy(&w, p, 2); v = w; }
            else if (s.component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) std::memcpy(&v, p, 4);
            else throw ModelError("accessor " + std::to_string(index) + " (indices) is not of unsigned integers");
            if (v >= vertices)
                throw ModelError("an index is " + std::to_string(v) + ", but its primitive has " +
                                 std::to_string(vertices) + " vertices");
            out[i] = v;
        }
        return out;
    }

    std::uint32_t group(int material) {
        if (material < -1 || material >= int(model_.materials.size()))
            throw ModelError("a primitive names material " + std::to_string(material) + ", which the file does not have");
        auto [found, added] = groups_.emplace(material, std::uint32_t(soup_.materials.size()));
        if (added) {
            FileMaterial m;
            if (material >= 0) {
                const tinygltf::Material& g = model_.materials[std::size_t(material)];
                const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
                m.kind = FileMaterial::Kind::gltf;
                m.name = g.name;
                if (pbr.baseColorFactor.size() >= 3)
                    m.base_color = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
                m.metallic = pbr.metallicFactor;
                m.roughness = pbr.roughnessFactor;
            } else {
                m.kind = FileMaterial::Kind::gltf;  // glTF's default material: white, metallic 1, roughness 1
            }
            soup_.materials.push_back(m);
            double_sided_.push_back(material >= 0 && model_.materials[std::size_t(material)].doubleSided);
        }
        return found->second;
    }

    void add_primitive(const tinygltf::Primitive& primitive, const glm::dmat4& transform) {
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            lines_or_points = true;
            return;
        }
        for (const auto& [name, value] : primitive.extensions)
            if (changes_geometry(name)) throw ModelError("a primitive uses the extension " + printable(name) +
                                                         ", which this program does not read (export without it)");
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) throw ModelError("a primitive has no POSITION");
        std::vector<dvec3> points = vectors(position->second, "positions");
        std::vector<dvec3> normals;
        const auto normal = primitive.attributes.find("NORMAL");
        if (normal != primitive.attributes.end()) {
            normals = vectors(normal->second, "normals");
            if (normals.size() != points.size()) throw ModelError("a primitive has not as many normals as positions");
        }
        std::vector<std::uint32_t> order;
        if (primitive.indices >= 0) {
            order = indices(primitive.indices, points.size());
        } else {
            order.resize(points.size());
            for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(i);
        }
        // Triangles from the list, strip or fan (glTF 2.0 §3.7.2.1).
        std::vector<std::uint32_t> triangles;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            triangles.assign(order.begin(), order.begin() + std::ptrdiff_t(order.size() / 3 * 3));
        } else {
            for (std::size_t i = 2; i < order.size(); ++i) {
                if (mode == TINYGLTF_MODE_TRIANGLE_FAN) triangles.insert(triangles.end(), {order[0], order[i - 1], order[i]});
                else if (i % 2 == 0) triangles.insert(triangles.end(), {order[i - 2], order[i - 1], order[i]});
                else triangles.insert(triangles.end(), {order[i - 1], order[i - 2], order[i]});
            }
        }
        const std::uint32_t g = group(primitive.material);
        const std::size_t sides = double_sided_[g] ? 2 : 1;
        if (soup_.groups.size() + sides * (triangles.size() / 3) > max_triangles_)
            throw ModelError("has more than the " + std::to_string(max_triangles_) + " triangles a scene may have");
        // World positions; normals by the inverse transpose; a mirroring transform reverses the winding.
        const glm::dmat3 linear(transform);
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
        const bool mirrored = glm::determinant(linear) < 0;
        const std::uint32_t base = std::uint32_t(soup_.positions.size());
        const std::int64_t normal_base = std::int64_t(soup_.normals.size());
        for (const dvec3& p : points) soup_.positions.push_back(dvec3(transform * glm::dvec4(p, 1.0)));
        for (const dvec3& n : normals) soup_.normals.push_back(normal_matrix * n);
        for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = triangles[t + std::size_t(mirrored && k > 0 ? 3 - k : k)];
                soup_.corners.push_back({base + v, normals.empty() ? -1 : normal_base + v});
            }
            soup_.groups.push_back(g);
        }
        if (sides == 2) add_back_faces(triangles, points.size(), base, normals.size(), normal_base, mirrored, g);
    }

    // A doubleSided material (glTF 2.0 §3.9.6: no back-face culling, the back
    // lit with its normal reversed) as the same triangles again, wound the
    // other way, with reversed normals, on copies of their positions (so that
    // normals made for a file without them smooth each side on its own): the
    // mesh pass, the reference and shadows then see two one-sided surfaces,
    // and every one of them keeps the spec's rule that only front faces shade.
    void add_back_faces(const std::vector<std::uint32_t>& triangles, std::size_t points, std::uint32_t base,
                        std::size_t normals, std::int64_t normal_base, bool mirrored, std::uint32_t g) {
        const std::uint32_t back = std::uint32_t(soup_.positions.size());
        const std::int64_t back_normals = std::int64_t(soup_.normals.size());
        for (std::size_t i = 0; i < points; ++i) {
            const dvec3 p = soup_.positions[base + i];
            soup_.positions.push_back(p);
        }
        for (std::size_t i = 0; i < normals; ++i) {
            const dvec3 n = soup_.normals[std::size_t(normal_base) + i];
            soup_.normals.push_back(-n);
        }
        for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = triangles[t + std::size_t(!mirrored && k > 0 ? 3 - k : k)];
                soup_.corners.push_back({back + v, normals == 0 ? -1 : back_normals + v});
            }
            soup_.groups.push_back(g);
        }
    }

    const tinygltf::Model& model_;
    Soup& soup_;
    std::size_t max_triangles_;
    std::map<int, std::uint32_t> groups_;
    std::vector<bool> double_sided_;  // per group: its material's doubleSided
};

}  // namespace

Soup parse_gltf(const std::string& bytes, bool binary, const SideFileReader& side_files, std::size_t max_triangles) {
    const char* json = bytes.data();
    std::size_t json_size = bytes.size();
    if (binary && !glb_json(bytes, &json, &json_size)) throw ModelError("is not a binary glTF file (.glb)");
    if (!binary && bytes.find_first_not_of(" \t\r\n") != std::string::npos && bytes[bytes.find_first_not_of(" \t\r\n")] != '{')
        throw ModelError("is not a glTF file (not JSON)");
    if (json_depth(json, json_size) > kMaxJsonDepth)
        throw ModelError("has JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");

    {
        const nlohmann::json doc = nlohmann::json::parse(json, json + json_size, nullptr, false);
        if (doc.is_discarded() || !doc.is_object()) throw ModelError("is not a valid glTF file: invalid JSON");
        // glTF 1.0 (its collections are objects, not arrays) is another format.
        const auto asset = doc.find("asset");
        if (asset != doc.end() && asset->is_object()) {
            const auto version = asset->find("version");
            if (version != asset->end() && version->is_string() && version->get<std::string>().rfind("2.", 0) != 0)
                throw ModelError("is not glTF 2.0 (asset.version says otherwise): export it as glTF 2.0");
        }
        const std::string problem = first_type_problem(doc, "");
        if (!problem.empty()) throw ModelError("is not a valid glTF file: " + problem);
    }

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    Files files{&side_files, {}};
    loader.SetFsCallbacks({file_exists, expand_path, read_whole_file, write_whole_file, &files});
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                                         reinterpret_cast<const unsigned char*>(bytes.data()),
                                                         unsigned(bytes.size()), "")
                           : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), "");
    if (!files.problem.empty()) throw ModelError(files.problem);
    if (!ok) throw ModelError("is not a valid glTF file: " + first_line(err));

    Soup soup;
    Reader reader(model, soup, max_triangles);
    reader.read();
    if (soup.groups.empty())
        throw ModelError(reader.lines_or_points ? "holds no triangles, only lines or points"
                                                : "holds no triangles (no mesh in its scene)");
    return soup;
}

}  // namespace m3055::model_file
