#include "tests/gpu/gltf_layout_rewriter.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <stdexcept>
#include <utility>

#include <glm/gtc/type_ptr.hpp>
#include <glm/gtc/quaternion.hpp>

namespace ml::test::layout {

namespace fs = std::filesystem;

namespace {

// What fills the bytes no accessor reads: as floats 3.4e38, so a reader that strays into them
// draws something nobody misses.
constexpr std::uint8_t kJunk = 0x7F;

std::size_t roundUp4(std::size_t n) { return (n + 3) / 4 * 4; }

std::size_t elementBytes(int componentType, int type) {
    return static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(componentType))) *
           static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type)));
}

// --- Reading -------------------------------------------------------------------------------------

double componentValue(const std::uint8_t* p, int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return static_cast<std::int8_t>(*p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

std::uint32_t readIndex(const std::uint8_t* p, int componentType) {
    if (componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw std::runtime_error("index component type " + std::to_string(componentType) + " is not unsigned");
    return static_cast<std::uint32_t>(componentValue(p, componentType));
}

const std::uint8_t* viewBytes(const tinygltf::Model& m, int view, std::size_t offset) {
    const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(view));
    return m.buffers.at(static_cast<std::size_t>(v.buffer)).data.data() + v.byteOffset + offset;
}

Stream readStream(const tinygltf::Model& m, int index) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(index));
    Stream s;
    s.componentType = a.componentType;
    s.type = a.type;
    s.normalized = a.normalized;
    s.elementSize = elementBytes(a.componentType, a.type);
    s.bytes.assign(a.count * s.elementSize, 0);
    if (a.bufferView >= 0) {
        const tinygltf::BufferView& v = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
        const std::size_t stride = v.byteStride != 0 ? v.byteStride : s.elementSize;
        const std::uint8_t* base = viewBytes(m, a.bufferView, a.byteOffset);
        for (std::size_t i = 0; i < a.count; ++i) std::memcpy(&s.bytes[i * s.elementSize], base + i * stride, s.elementSize);
    }
    if (a.sparse.isSparse) {
        const auto& sp = a.sparse;
        const std::size_t indexSize = elementBytes(sp.indices.componentType, TINYGLTF_TYPE_SCALAR);
        const std::uint8_t* indices = viewBytes(m, sp.indices.bufferView, static_cast<std::size_t>(sp.indices.byteOffset));
        const std::uint8_t* values = viewBytes(m, sp.values.bufferView, static_cast<std::size_t>(sp.values.byteOffset));
        for (std::size_t k = 0; k < static_cast<std::size_t>(sp.count); ++k) {
            const std::uint32_t at = readIndex(indices + k * indexSize, sp.indices.componentType);
            std::memcpy(&s.bytes[at * s.elementSize], values + k * s.elementSize, s.elementSize);
        }
    }
    return s;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& m, int index) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(index));
    const std::size_t size = elementBytes(a.componentType, TINYGLTF_TYPE_SCALAR);
    const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
    const std::size_t stride = v.byteStride != 0 ? v.byteStride : size;
    const std::uint8_t* base = viewBytes(m, a.bufferView, a.byteOffset);
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) out[i] = readIndex(base + i * stride, a.componentType);
    return out;
}

// --- Element helpers -------------------------------------------------------------------------------

glm::vec3 vec3At(const Stream& s, std::size_t i) {
    glm::vec3 v;
    std::memcpy(&v, &s.bytes[i * s.elementSize], 12);
    return v;
}
void setVec3(Stream& s, std::size_t i, const glm::vec3& v) { std::memcpy(&s.bytes[i * s.elementSize], &v, 12); }
glm::vec4 vec4At(const Stream& s, std::size_t i) {
    glm::vec4 v;
    std::memcpy(&v, &s.bytes[i * s.elementSize], 16);
    return v;
}
void setVec4(Stream& s, std::size_t i, const glm::vec4& v) { std::memcpy(&s.bytes[i * s.elementSize], &v, 16); }

bool isFloat(const Stream& s, int type) { return s.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && s.type == type; }

// The elements of `s` in the order `order` names (element k of the result is order[k] of `s`).
Stream gathered(const Stream& s, const std::vector<std::uint32_t>& order) {
    Stream out = s;
    out.bytes.resize(order.size() * s.elementSize);
    for (std::size_t k = 0; k < order.size(); ++k)
        std::memcpy(&out.bytes[k * s.elementSize], &s.bytes[order[k] * s.elementSize], s.elementSize);
    return out;
}

VertexSet gatheredSet(const VertexSet& set, const std::vector<std::uint32_t>& order) {
    VertexSet out;
    for (const auto& [name, s] : set.attributes) out.attributes[name] = gathered(s, order);
    for (const auto& target : set.targets) {
        auto& t = out.targets.emplace_back();
        for (const auto& [name, s] : target) t[name] = gathered(s, order);
    }
    return out;
}

// A format signature: sets with equal signatures can be concatenated.
std::string signature(const VertexSet& set) {
    std::string sig;
    const auto add = [&sig](const std::map<std::string, Stream>& streams) {
        for (const auto& [name, s] : streams)
            sig += name + ":" + std::to_string(s.componentType) + "/" + std::to_string(s.type) + "/" + (s.normalized ? "n" : "") + ";";
        sig += "|";
    };
    add(set.attributes);
    for (const auto& t : set.targets) add(t);
    return sig;
}

void append(VertexSet& to, const VertexSet& from) {
    for (auto& [name, s] : to.attributes) {
        const Stream& more = from.attributes.at(name);
        s.bytes.insert(s.bytes.end(), more.bytes.begin(), more.bytes.end());
    }
    for (std::size_t t = 0; t < to.targets.size(); ++t)
        for (auto& [name, s] : to.targets[t]) {
            const Stream& more = from.targets[t].at(name);
            s.bytes.insert(s.bytes.end(), more.bytes.begin(), more.bytes.end());
        }
}

// Drops the sets no primitive uses and renumbers the rest.
void compactSets(Mesh& mesh) {
    std::vector<int> newIndex(mesh.sets.size(), -1);
    std::vector<VertexSet> kept;
    for (Primitive& p : mesh.primitives) {
        if (newIndex[p.set] < 0) {
            newIndex[p.set] = static_cast<int>(kept.size());
            kept.push_back(std::move(mesh.sets[p.set]));
        }
        p.set = static_cast<std::size_t>(newIndex[p.set]);
    }
    mesh.sets = std::move(kept);
}

// A reproducible permutation (Fisher-Yates over splitmix64), the same on every machine.
std::vector<std::uint32_t> permutation(std::size_t n, std::uint64_t seed) {
    std::vector<std::uint32_t> p(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = static_cast<std::uint32_t>(i);
    std::uint64_t state = seed;
    const auto next = [&state] {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    };
    for (std::size_t i = n; i > 1; --i) std::swap(p[i - 1], p[next() % i]);
    return p;
}

glm::dmat4 localMatrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());
    glm::dmat4 m(1.0);
    if (n.translation.size() == 3) m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    if (n.rotation.size() == 4) m *= glm::mat4_cast(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
    if (n.scale.size() == 3) m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
}

// --- Writing -------------------------------------------------------------------------------------

// Appends the rewritten streams to one new buffer of the model, as `layout` lays them out.
class Encoder {
public:
    Encoder(tinygltf::Model& model, const Layout& layout) : m_(model), l_(layout), buffer_(static_cast<int>(model.buffers.size())) {
        m_.buffers.emplace_back();
    }
    void finish() { m_.buffers[static_cast<std::size_t>(buffer_)].data = std::move(bin_); }

    // The accessors of a vertex set: name -> accessor, and the same per morph target.
    std::pair<std::map<std::string, int>, std::vector<std::map<std::string, int>>> set(const VertexSet& set) {
        std::map<std::string, int> ids;
        std::vector<const std::pair<const std::string, Stream>*> interleave;
        for (const auto& entry : set.attributes) {
            if (sparseFor(entry.first) != Sparse::None) ids[entry.first] = sparse(entry.second, entry.first == "POSITION", sparseFor(entry.first));
            else if (l_.interleaved) interleave.push_back(&entry);
            else ids[entry.first] = separate(entry.second, entry.first == "POSITION");
        }
        if (!interleave.empty()) interleaved(interleave, ids);
        std::vector<std::map<std::string, int>> targets;
        for (const auto& target : set.targets) {
            auto& t = targets.emplace_back();
            for (const auto& [name, s] : target) t[name] = separate(s, name == "POSITION");
        }
        return {ids, targets};
    }

    int indices(const std::vector<std::uint32_t>& values, int componentType) {
        const std::size_t size = elementBytes(componentType, TINYGLTF_TYPE_SCALAR);
        const std::size_t start = beginView();
        junk(l_.accessorOffset);
        for (std::uint32_t v : values) {
            std::uint8_t bytes[4];
            std::memcpy(bytes, &v, 4);  // little-endian: the low bytes first
            bin_.insert(bin_.end(), bytes, bytes + size);
        }
        const int view = addView(start, bin_.size() - start, 0, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        tinygltf::Accessor a;
        a.bufferView = view;
        a.byteOffset = l_.accessorOffset;
        a.componentType = componentType;
        a.type = TINYGLTF_TYPE_SCALAR;
        a.count = values.size();
        return add(std::move(a));
    }

private:
    Sparse sparseFor(const std::string& name) const {
        if (l_.sparse == Sparse::ZeroBase && name == "POSITION") return Sparse::ZeroBase;
        if (l_.sparse == Sparse::OverBase && (name == "POSITION" || name == "NORMAL")) return Sparse::OverBase;
        return Sparse::None;
    }

    void junk(std::size_t n) { bin_.insert(bin_.end(), n, kJunk); }
    std::size_t beginView() {
        junk(roundUp4(bin_.size()) - bin_.size());
        junk(l_.viewPadding);
        return bin_.size();
    }
    int addView(std::size_t offset, std::size_t length, std::size_t stride, int target) {
        tinygltf::BufferView v;
        v.buffer = buffer_;
        v.byteOffset = offset;
        v.byteLength = length;
        v.byteStride = stride;
        v.target = target;
        m_.bufferViews.push_back(std::move(v));
        return static_cast<int>(m_.bufferViews.size()) - 1;
    }
    int add(tinygltf::Accessor a) {
        m_.accessors.push_back(std::move(a));
        return static_cast<int>(m_.accessors.size()) - 1;
    }
    static tinygltf::Accessor accessorFor(const Stream& s, bool position) {
        tinygltf::Accessor a;
        a.componentType = s.componentType;
        a.type = s.type;
        a.normalized = s.normalized;
        a.count = s.count();
        if (position && s.count() > 0) {
            const std::size_t components = static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(s.type)));
            const std::size_t size = s.elementSize / components;
            a.minValues.assign(components, std::numeric_limits<double>::max());
            a.maxValues.assign(components, std::numeric_limits<double>::lowest());
            for (std::size_t i = 0; i < s.count(); ++i)
                for (std::size_t c = 0; c < components; ++c) {
                    const double v = componentValue(&s.bytes[i * s.elementSize + c * size], s.componentType);
                    a.minValues[c] = std::min(a.minValues[c], v);
                    a.maxValues[c] = std::max(a.maxValues[c], v);
                }
        }
        return a;
    }

    int separate(const Stream& s, bool position) {
        // Vertex elements start on 4-byte boundaries: a 2-byte element gets a stride.
        const bool strided = l_.extraStride != 0 || s.elementSize % 4 != 0;
        const std::size_t stride = strided ? roundUp4(s.elementSize) + l_.extraStride : s.elementSize;
        const std::size_t start = beginView();
        junk(l_.accessorOffset);
        for (std::size_t i = 0; i < s.count(); ++i) {
            bin_.insert(bin_.end(), s.bytes.begin() + static_cast<std::ptrdiff_t>(i * s.elementSize),
                        s.bytes.begin() + static_cast<std::ptrdiff_t>((i + 1) * s.elementSize));
            if (i + 1 < s.count()) junk(stride - s.elementSize);
        }
        tinygltf::Accessor a = accessorFor(s, position);
        a.bufferView = addView(start, bin_.size() - start, strided ? stride : 0, TINYGLTF_TARGET_ARRAY_BUFFER);
        a.byteOffset = l_.accessorOffset;
        return add(std::move(a));
    }

    void interleaved(const std::vector<const std::pair<const std::string, Stream>*>& streams, std::map<std::string, int>& ids) {
        std::vector<std::size_t> offsets;
        std::size_t record = 0;
        for (const auto* entry : streams) {
            offsets.push_back(record);
            record += roundUp4(entry->second.elementSize);
        }
        record += l_.extraStride;
        if (record > 252) throw std::runtime_error("interleaved record of " + std::to_string(record) + " bytes is over glTF's byteStride limit");
        const std::size_t count = streams.front()->second.count();
        const std::size_t start = beginView();
        const std::size_t at = bin_.size();
        bin_.resize(at + count * record, kJunk);
        for (std::size_t k = 0; k < streams.size(); ++k) {
            const Stream& s = streams[k]->second;
            for (std::size_t i = 0; i < count; ++i)
                std::memcpy(&bin_[at + i * record + offsets[k]], &s.bytes[i * s.elementSize], s.elementSize);
        }
        const int view = addView(start, bin_.size() - start, record, TINYGLTF_TARGET_ARRAY_BUFFER);
        for (std::size_t k = 0; k < streams.size(); ++k) {
            tinygltf::Accessor a = accessorFor(streams[k]->second, streams[k]->first == "POSITION");
            a.bufferView = view;
            a.byteOffset = offsets[k];
            ids[streams[k]->first] = add(std::move(a));
        }
    }

    int sparse(const Stream& s, bool position, Sparse mode) {
        tinygltf::Accessor a = accessorFor(s, position);
        std::vector<std::uint32_t> substituted;
        for (std::size_t i = 0; i < s.count(); ++i) {
            const auto first = s.bytes.begin() + static_cast<std::ptrdiff_t>(i * s.elementSize);
            if (mode == Sparse::OverBase || std::any_of(first, first + static_cast<std::ptrdiff_t>(s.elementSize), [](std::uint8_t b) { return b != 0; }))
                substituted.push_back(static_cast<std::uint32_t>(i));
        }
        if (mode == Sparse::OverBase) {
            const std::size_t start = beginView();
            junk(s.bytes.size());
            a.bufferView = addView(start, s.bytes.size(), 0, TINYGLTF_TARGET_ARRAY_BUFFER);
        }
        if (substituted.empty()) return add(std::move(a));  // all zeros: no view, no substitutes
        const std::uint32_t last = substituted.back();
        const int indexType = last <= 0xFF ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
                              : last <= 0xFFFF ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                               : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        const std::size_t indexSize = elementBytes(indexType, TINYGLTF_TYPE_SCALAR);
        std::size_t start = beginView();
        for (std::uint32_t v : substituted) {
            std::uint8_t bytes[4];
            std::memcpy(bytes, &v, 4);
            bin_.insert(bin_.end(), bytes, bytes + indexSize);
        }
        const int indexView = addView(start, bin_.size() - start, 0, 0);
        start = beginView();
        for (std::uint32_t v : substituted)
            bin_.insert(bin_.end(), s.bytes.begin() + static_cast<std::ptrdiff_t>(v * s.elementSize),
                        s.bytes.begin() + static_cast<std::ptrdiff_t>((v + 1) * s.elementSize));
        const int valueView = addView(start, bin_.size() - start, 0, 0);
        a.sparse.isSparse = true;
        a.sparse.count = static_cast<int>(substituted.size());
        a.sparse.indices.bufferView = indexView;
        a.sparse.indices.byteOffset = 0;
        a.sparse.indices.componentType = indexType;
        a.sparse.values.bufferView = valueView;
        a.sparse.values.byteOffset = 0;
        return add(std::move(a));
    }

    tinygltf::Model& m_;
    const Layout& l_;
    int buffer_;
    std::vector<std::uint8_t> bin_;
};

int indexTypeFor(IndexWidth width, int stored, std::uint32_t maxIndex) {
    const int u8 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, u16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
              u32 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    // glTF: an index never holds its type's largest value (the primitive restart value).
    const auto fits = [maxIndex](int type) {
        return type == u32 || (type == u16 && maxIndex < 0xFFFF) || (type == u8 && maxIndex < 0xFF);
    };
    switch (width) {
    case IndexWidth::AsStored: return fits(stored) ? stored : fits(u16) ? u16 : u32;
    case IndexWidth::Narrowest: return fits(u8) ? u8 : fits(u16) ? u16 : u32;
    case IndexWidth::U16: return fits(u16) ? u16 : u32;
    case IndexWidth::U32: return u32;
    }
    return u32;
}

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0, b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const std::uint32_t triple = std::uint32_t{bytes[i]} << 16 | b1 << 8 | b2;
        out += kAlphabet[(triple >> 18) & 63];
        out += kAlphabet[(triple >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(triple >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[triple & 63] : '=';
    }
    return out;
}

// Images stay encoded as the file holds them: a file image keeps its uri (the file is copied), an
// image in a data URI (which tinygltf decodes and forgets) is written back as the same bytes.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + std::max(size, 0));
    image->as_is = true;
    return true;
}
bool writeEncodedImage(const std::string*, const std::string*, const tinygltf::Image* image, bool, std::string* uri, void*) {
    if (!image->uri.empty() || image->bufferView >= 0 || image->image.empty()) return false;  // as the file gave it
    *uri = "data:" + (image->mimeType.empty() ? std::string("image/png") : image->mimeType) + ";base64," + base64(image->image);
    return true;
}

}  // namespace

std::size_t VertexSet::count() const { return attributes.empty() ? 0 : attributes.begin()->second.count(); }

// --- Reading a file ----------------------------------------------------------------------------------

Rewriter::Rewriter(const fs::path& file) : sourceDir_(file.parent_path()) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keepEncodedImage, nullptr);
    std::string err, warn;
    const bool binary = file.extension() == ".glb";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, file.string())
                           : loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
    if (!ok) throw std::runtime_error(file.string() + ": tinygltf: " + err);
    for (const std::string& ext : model.extensionsRequired)
        if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression")
            throw std::runtime_error(file.string() + ": compressed files are not rewritten (" + ext + ")");

    for (const tinygltf::Mesh& source : model.meshes) {
        Mesh& mesh = meshes.emplace_back();
        mesh.header = source;
        mesh.header.primitives.clear();
        std::map<std::string, std::size_t> setOf;  // accessor numbers -> set, so shared accessors stay shared
        for (const tinygltf::Primitive& p : source.primitives) {
            std::string key;
            for (const auto& [name, accessor] : p.attributes) key += name + "=" + std::to_string(accessor) + ";";
            for (const auto& target : p.targets) {
                key += "|";
                for (const auto& [name, accessor] : target) key += name + "=" + std::to_string(accessor) + ";";
            }
            auto found = setOf.find(key);
            if (found == setOf.end()) {
                VertexSet set;
                for (const auto& [name, accessor] : p.attributes) set.attributes[name] = readStream(model, accessor);
                for (const auto& target : p.targets) {
                    auto& t = set.targets.emplace_back();
                    for (const auto& [name, accessor] : target) t[name] = readStream(model, accessor);
                }
                found = setOf.emplace(key, mesh.sets.size()).first;
                mesh.sets.push_back(std::move(set));
            }
            Primitive prim;
            prim.set = found->second;
            prim.indexed = p.indices >= 0;
            if (prim.indexed) {
                prim.indices = readIndices(model, p.indices);
                prim.indexType = model.accessors[static_cast<std::size_t>(p.indices)].componentType;
            }
            prim.mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
            prim.material = p.material;
            prim.extras = p.extras;
            prim.extensions = p.extensions;
            mesh.primitives.push_back(std::move(prim));
        }
    }
}

// --- Writing a file ----------------------------------------------------------------------------------

fs::path Rewriter::write(const fs::path& dir, const std::string& name) {
    fs::create_directories(dir);
    tinygltf::Model out = model;
    Encoder encoder(out, layout);
    out.meshes.clear();
    for (const Mesh& mesh : meshes) {
        tinygltf::Mesh m = mesh.header;
        std::map<std::size_t, std::pair<std::map<std::string, int>, std::vector<std::map<std::string, int>>>> written;
        for (const Primitive& p : mesh.primitives) {
            auto found = written.find(p.set);
            if (found == written.end()) found = written.emplace(p.set, encoder.set(mesh.sets[p.set])).first;
            tinygltf::Primitive tp;
            tp.attributes = found->second.first;
            tp.targets = found->second.second;
            tp.mode = p.mode;
            tp.material = p.material;
            tp.extras = p.extras;
            tp.extensions = p.extensions;
            if (p.indexed) {
                const std::uint32_t maxIndex = p.indices.empty() ? 0 : *std::max_element(p.indices.begin(), p.indices.end());
                tp.indices = encoder.indices(p.indices, indexTypeFor(layout.indexWidth, p.indexType, maxIndex));
            }
            m.primitives.push_back(std::move(tp));
        }
        out.meshes.push_back(std::move(m));
    }
    encoder.finish();
    for (std::size_t i = 0; i < out.buffers.size(); ++i) out.buffers[i].uri = name + "_" + std::to_string(i) + ".bin";
    for (const tinygltf::Image& image : out.images) {
        if (image.uri.empty() || image.uri.rfind("data:", 0) == 0) continue;
        const fs::path to = dir / image.uri;
        fs::create_directories(to.parent_path());
        fs::copy_file(sourceDir_ / image.uri, to, fs::copy_options::overwrite_existing);
    }
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(&writeEncodedImage, nullptr);
    const fs::path file = dir / (name + ".gltf");
    if (!writer.WriteGltfSceneToFile(&out, file.string(), false, false, true, false))
        throw std::runtime_error(file.string() + ": tinygltf could not write it");
    return file;
}

// --- The changes ---------------------------------------------------------------------------------

int Rewriter::defaultScene() const { return model.defaultScene >= 0 ? model.defaultScene : 0; }

bool Rewriter::onlyTriangles(const Mesh& mesh, std::size_t s) const {
    for (const Primitive& p : mesh.primitives)
        if (p.set == s && p.mode != TINYGLTF_MODE_TRIANGLES) return false;
    return true;
}

namespace {
// Gives a non-indexed triangle primitive indices 0..n-1 over its set (the same triangles).
void indexWhole(Primitive& p, std::size_t count) {
    if (p.indexed) return;
    p.indexed = true;
    p.indexType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    p.indices.resize(count);
    for (std::size_t i = 0; i < count; ++i) p.indices[i] = static_cast<std::uint32_t>(i);
}
}  // namespace

bool Rewriter::addUnusedVertices(std::size_t count, std::string& why) {
    bool changed = false;
    for (Mesh& mesh : meshes) {
        for (std::size_t s = 0; s < mesh.sets.size(); ++s) {
            if (!onlyTriangles(mesh, s)) continue;
            VertexSet& set = mesh.sets[s];
            const std::size_t n = set.count();
            if (n == 0) continue;
            for (Primitive& p : mesh.primitives)
                if (p.set == s) {
                    indexWhole(p, n);
                    for (std::uint32_t& i : p.indices) i += static_cast<std::uint32_t>(count);
                }
            // A floor far below and wide of the set's own vertices (float positions), else
            // copies of the first vertex.
            std::vector<glm::vec3> floor;
            const auto position = set.attributes.find("POSITION");
            if (position != set.attributes.end() && isFloat(position->second, TINYGLTF_TYPE_VEC3)) {
                glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
                for (std::size_t i = 0; i < n; ++i) {
                    lo = glm::min(lo, vec3At(position->second, i));
                    hi = glm::max(hi, vec3At(position->second, i));
                }
                const glm::vec3 c = 0.5f * (lo + hi);
                const float d = std::max(glm::length(hi - lo), 1.0f);
                for (std::size_t k = 0; k < 2 * count; ++k) {
                    const float sx = (k & 1) ? 1.0f : -1.0f, sz = (k & 2) ? 1.0f : -1.0f, far = 10.0f + float(k / 4);
                    floor.push_back({c.x + sx * far * d, lo.y - 5.0f * d, c.z + sz * far * d});
                }
            }
            const auto pad = [&](Stream& st, bool isPosition, bool zero) {
                std::vector<std::uint8_t> before, after;
                for (std::size_t k = 0; k < 2 * count; ++k) {
                    std::vector<std::uint8_t>& to = k < count ? before : after;
                    const std::size_t at = to.size();
                    if (zero) to.resize(at + st.elementSize, 0);
                    else to.insert(to.end(), st.bytes.begin(), st.bytes.begin() + static_cast<std::ptrdiff_t>(st.elementSize));
                    if (isPosition && !floor.empty()) std::memcpy(&to[at], &floor[k], 12);
                }
                st.bytes.insert(st.bytes.begin(), before.begin(), before.end());
                st.bytes.insert(st.bytes.end(), after.begin(), after.end());
            };
            for (auto& [name, st] : set.attributes) pad(st, name == "POSITION", false);
            for (auto& target : set.targets)
                for (auto& [name, st] : target) pad(st, false, true);  // no displacement
            changed = true;
        }
    }
    if (!changed) why = "no triangle primitive";
    return changed;
}

bool Rewriter::addFarQuad(const glm::vec3& centre, float halfSize, std::string& why) {
    if (model.scenes.empty()) {
        why = "the file has no scene";
        return false;
    }
    tinygltf::Material material;
    material.name = "far quad";
    material.pbrMetallicRoughness.baseColorFactor = {0.6, 0.5, 0.4, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    model.materials.push_back(material);

    Mesh mesh;
    mesh.header.name = "far quad";
    VertexSet& set = mesh.sets.emplace_back();
    Stream positions, normals;
    const float h = halfSize;
    const glm::vec3 corners[4] = {centre + glm::vec3(-h, 0, -h), centre + glm::vec3(-h, 0, h), centre + glm::vec3(h, 0, h),
                                  centre + glm::vec3(h, 0, -h)};
    positions.bytes.resize(4 * 12);
    normals.bytes.resize(4 * 12);
    for (std::size_t i = 0; i < 4; ++i) {
        setVec3(positions, i, corners[i]);
        setVec3(normals, i, {0.0f, 1.0f, 0.0f});
    }
    set.attributes["POSITION"] = positions;
    set.attributes["NORMAL"] = normals;
    Primitive p;
    p.indices = {0, 1, 2, 0, 2, 3};
    p.indexType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    p.material = static_cast<int>(model.materials.size()) - 1;
    mesh.primitives.push_back(p);
    meshes.push_back(std::move(mesh));

    tinygltf::Node node;
    node.name = "far quad";
    node.mesh = static_cast<int>(meshes.size()) - 1;
    model.nodes.push_back(node);
    model.scenes[static_cast<std::size_t>(defaultScene())].nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
    return true;
}

bool Rewriter::shareAccessors(std::string& why) {
    bool changed = false;
    for (Mesh& mesh : meshes) {
        std::vector<std::size_t> users(mesh.sets.size(), 0);
        for (const Primitive& p : mesh.primitives) ++users[p.set];
        // Triangle primitives with a set of their own, grouped by format.
        std::map<std::string, std::vector<std::size_t>> groups;
        for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
            const Primitive& p = mesh.primitives[i];
            if (p.mode == TINYGLTF_MODE_TRIANGLES && users[p.set] == 1) groups[signature(mesh.sets[p.set])].push_back(i);
        }
        for (auto& [sig, prims] : groups) {
            if (prims.size() < 2) continue;
            const std::size_t shared = mesh.primitives[prims[0]].set;
            indexWhole(mesh.primitives[prims[0]], mesh.sets[shared].count());
            for (std::size_t k = 1; k < prims.size(); ++k) {
                Primitive& p = mesh.primitives[prims[k]];
                indexWhole(p, mesh.sets[p.set].count());
                const auto offset = static_cast<std::uint32_t>(mesh.sets[shared].count());
                append(mesh.sets[shared], mesh.sets[p.set]);
                for (std::uint32_t& i : p.indices) i += offset;
                p.set = shared;
            }
            changed = true;
        }
        if (groups.size() == 1 && groups.begin()->second.size() == 1) {
            // One triangle primitive: two halves of its triangles, one set of accessors.
            const std::size_t at = groups.begin()->second[0];
            Primitive& p = mesh.primitives[at];
            indexWhole(p, mesh.sets[p.set].count());
            const std::size_t triangles = p.indices.size() / 3;
            if (triangles >= 2) {
                Primitive second = p;
                const auto half = static_cast<std::ptrdiff_t>(triangles / 2 * 3);
                second.indices.assign(p.indices.begin() + half, p.indices.end());
                p.indices.resize(static_cast<std::size_t>(half));
                mesh.primitives.insert(mesh.primitives.begin() + static_cast<std::ptrdiff_t>(at) + 1, std::move(second));
                changed = true;
            }
        }
        compactSets(mesh);
    }
    if (!changed) why = "no mesh with triangle primitives to share accessors";
    return changed;
}

bool Rewriter::deindex(std::string& why) {
    bool changed = false;
    for (Mesh& mesh : meshes) {
        for (Primitive& p : mesh.primitives) {
            if (!p.indexed || p.mode != TINYGLTF_MODE_TRIANGLES) continue;
            const VertexSet& set = mesh.sets[p.set];
            // Without NORMAL (or TANGENT under a normal map) the loader generates them from the
            // triangles that share a vertex: without indices none share, and the shading changes.
            if (!set.attributes.count("NORMAL")) {
                why = "a primitive has no NORMAL (the loader's generated normals depend on shared vertices)";
                return false;
            }
            const bool normalMapped = p.material >= 0 && model.materials[static_cast<std::size_t>(p.material)].normalTexture.index >= 0;
            if (normalMapped && !set.attributes.count("TANGENT")) {
                why = "a normal-mapped primitive has no TANGENT (the loader's generated tangents depend on shared vertices)";
                return false;
            }
        }
    }
    for (Mesh& mesh : meshes) {
        for (Primitive& p : mesh.primitives) {
            if (!p.indexed || p.mode != TINYGLTF_MODE_TRIANGLES) continue;
            mesh.sets.push_back(gatheredSet(mesh.sets[p.set], p.indices));
            p.set = mesh.sets.size() - 1;
            p.indexed = false;
            p.indices.clear();
            changed = true;
        }
        compactSets(mesh);
    }
    if (!changed) why = "no indexed triangle primitive";
    return changed;
}

bool Rewriter::bakeHierarchy(std::string& why) {
    if (!model.skins.empty() || !model.animations.empty()) {
        why = "the file is skinned or animated (a baked vertex would not follow its joints or nodes)";
        return false;
    }
    if (model.scenes.empty()) {
        why = "the file has no scene";
        return false;
    }
    for (const Mesh& mesh : meshes) {
        for (const VertexSet& set : mesh.sets) {
            if (!set.targets.empty()) {
                why = "a mesh has morph targets";
                return false;
            }
            const auto p = set.attributes.find("POSITION");
            const auto n = set.attributes.find("NORMAL");
            const auto t = set.attributes.find("TANGENT");
            if (p == set.attributes.end() || !isFloat(p->second, TINYGLTF_TYPE_VEC3) ||
                (n != set.attributes.end() && !isFloat(n->second, TINYGLTF_TYPE_VEC3)) ||
                (t != set.attributes.end() && !isFloat(t->second, TINYGLTF_TYPE_VEC4))) {
                why = "positions, normals or tangents that are not floats";
                return false;
            }
        }
        for (const Primitive& p : mesh.primitives)
            if (p.mode != TINYGLTF_MODE_TRIANGLES) {
                why = "a primitive that is not a triangle list";
                return false;
            }
    }

    std::vector<tinygltf::Node> flat;
    const std::size_t originalMeshes = meshes.size();
    bool baked = false;
    const auto visit = [&](auto&& self, int index, const glm::dmat4& parent) -> void {
        const tinygltf::Node& node = model.nodes.at(static_cast<std::size_t>(index));
        const glm::dmat4 world = parent * localMatrix(node);
        tinygltf::Node rest = node;
        rest.children.clear();
        rest.translation.clear();
        rest.rotation.clear();
        rest.scale.clear();
        rest.matrix.assign(glm::value_ptr(world), glm::value_ptr(world) + 16);
        const bool instanced = node.extensions.count("EXT_mesh_gpu_instancing") != 0;
        if (node.mesh >= 0 && !instanced) {
            Mesh copy = meshes.at(static_cast<std::size_t>(node.mesh));
            const glm::dmat3 m3(world);
            const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(m3));
            const bool mirrored = glm::determinant(m3) < 0.0;
            for (VertexSet& set : copy.sets) {
                Stream& positions = set.attributes.at("POSITION");
                for (std::size_t i = 0; i < positions.count(); ++i)
                    setVec3(positions, i, glm::vec3(world * glm::dvec4(glm::dvec3(vec3At(positions, i)), 1.0)));
                if (auto n = set.attributes.find("NORMAL"); n != set.attributes.end())
                    for (std::size_t i = 0; i < n->second.count(); ++i)
                        setVec3(n->second, i, glm::vec3(glm::normalize(normalMatrix * glm::dvec3(vec3At(n->second, i)))));
                if (auto t = set.attributes.find("TANGENT"); t != set.attributes.end())
                    for (std::size_t i = 0; i < t->second.count(); ++i) {
                        const glm::vec4 v = vec4At(t->second, i);
                        const glm::vec3 xyz(glm::normalize(m3 * glm::dvec3(v)));
                        setVec4(t->second, i, glm::vec4(xyz, mirrored ? -v.w : v.w));
                    }
            }
            if (mirrored)
                for (Primitive& p : copy.primitives) {
                    indexWhole(p, copy.sets[p.set].count());
                    for (std::size_t k = 0; k + 2 < p.indices.size(); k += 3) std::swap(p.indices[k + 1], p.indices[k + 2]);
                }
            meshes.push_back(std::move(copy));
            tinygltf::Node bakedNode;
            bakedNode.name = node.name;
            bakedNode.mesh = static_cast<int>(meshes.size()) - 1;
            flat.push_back(bakedNode);
            baked = true;
            rest.mesh = -1;
        }
        if (rest.mesh >= 0 || rest.camera >= 0 || !rest.extensions.empty()) flat.push_back(rest);
        for (int child : node.children) self(self, child, world);
    };
    for (int root : model.scenes[static_cast<std::size_t>(defaultScene())].nodes) visit(visit, root, glm::dmat4(1.0));
    if (!baked) {
        meshes.resize(originalMeshes);
        why = "no node draws a mesh that can be baked";
        return false;
    }
    model.nodes = flat;
    tinygltf::Scene scene = model.scenes[static_cast<std::size_t>(defaultScene())];
    scene.nodes.clear();
    for (std::size_t i = 0; i < flat.size(); ++i) scene.nodes.push_back(static_cast<int>(i));
    model.scenes = {scene};
    model.defaultScene = 0;
    return true;
}

bool Rewriter::shuffleTriangles(std::uint32_t seed, std::string& why) {
    bool changed = false;
    std::uint64_t salt = seed;
    for (Mesh& mesh : meshes)
        for (Primitive& p : mesh.primitives) {
            if (p.mode != TINYGLTF_MODE_TRIANGLES) continue;
            indexWhole(p, mesh.sets[p.set].count());
            const std::size_t triangles = p.indices.size() / 3;
            if (triangles < 2) continue;
            const std::vector<std::uint32_t> order = permutation(triangles, ++salt * 7919);
            std::vector<std::uint32_t> out(p.indices.size());
            for (std::size_t t = 0; t < triangles; ++t)
                for (int c = 0; c < 3; ++c) out[3 * t + static_cast<std::size_t>(c)] = p.indices[3 * order[t] + static_cast<std::size_t>(c)];
            p.indices = std::move(out);
            changed = true;
        }
    if (!changed) why = "no triangle primitive with two triangles or more";
    return changed;
}

bool Rewriter::shuffleVertices(std::uint32_t seed, std::string& why) {
    bool changed = false;
    std::uint64_t salt = seed;
    for (Mesh& mesh : meshes)
        for (std::size_t s = 0; s < mesh.sets.size(); ++s) {
            if (!onlyTriangles(mesh, s) || mesh.sets[s].count() < 2) continue;
            const std::size_t n = mesh.sets[s].count();
            // Vertex i moves to place[i].
            const std::vector<std::uint32_t> place = permutation(n, ++salt * 104729);
            std::vector<std::uint32_t> from(n);
            for (std::size_t i = 0; i < n; ++i) from[place[i]] = static_cast<std::uint32_t>(i);
            mesh.sets[s] = gatheredSet(mesh.sets[s], from);
            for (Primitive& p : mesh.primitives)
                if (p.set == s) {
                    indexWhole(p, n);
                    for (std::uint32_t& i : p.indices) i = place[i];
                }
            changed = true;
        }
    if (!changed) why = "no vertex set of triangles";
    return changed;
}

bool Rewriter::rotateCorners(std::string& why) {
    bool changed = false;
    for (Mesh& mesh : meshes)
        for (Primitive& p : mesh.primitives) {
            if (p.mode != TINYGLTF_MODE_TRIANGLES) continue;
            indexWhole(p, mesh.sets[p.set].count());
            for (std::size_t k = 0; k + 2 < p.indices.size(); k += 3) std::rotate(&p.indices[k], &p.indices[k + 1], &p.indices[k + 3]);
            changed = true;
        }
    if (!changed) why = "no triangle primitive";
    return changed;
}

bool Rewriter::layoutApplies(std::string& why) const {
    for (const Mesh& mesh : meshes)
        for (const Primitive& p : mesh.primitives) {
            if (!p.indexed) continue;
            const std::uint32_t maxIndex = p.indices.empty() ? 0 : *std::max_element(p.indices.begin(), p.indices.end());
            if (indexTypeFor(layout.indexWidth, p.indexType, maxIndex) != p.indexType) return true;
        }
    if (layout.indexWidth != IndexWidth::AsStored) {
        why = layout.indexWidth == IndexWidth::Narrowest ? "no indexed primitive fits narrower indices"
                                                         : "every indexed primitive already has this index width";
        return false;
    }
    return true;
}

}  // namespace ml::test::layout
