// glTF 2.0 (.gltf and .glb) into the scene model, through tinygltf 2.7.
//
// tinygltf parses the JSON and fetches buffers, but checks little of what the model then refers
// to: buffer views, accessors, indices and node links may point anywhere. Everything this file
// reads from a tinygltf::Model is therefore bounds-checked here first, and every allocation is
// bounded by bytes actually present in the input or by the limits below, so that bad input ends
// in one SceneError line rather than a crash, a hang or a runaway allocation.
//
// The work, in order: read the file (and check a GLB container by hand), pre-check the JSON
// text, let tinygltf parse it, check what tinygltf does not, flatten the default scene's node
// trees with an explicit stack, and append each mesh instance's triangles in world space.
#include "scenes/gltf_loader.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

// The implementation lives in Debian's libtinygltf.so (built with stb), so no
// TINYGLTF_IMPLEMENTATION here; stb_image is used directly to decode base-colour images.
#include <stb_image.h>
#include <tiny_gltf.h>

namespace ml {
namespace {

namespace fs = std::filesystem;

// --- Limits --------------------------------------------------------------------------------------
// tinygltf passes sizes as int / unsigned int, so files past 2 GiB cannot be handed to it.
constexpr std::uintmax_t kMaxFileBytes = INT_MAX;
// tinygltf turns `extras` and `extensions` into tinygltf::Value recursively; a 100,000-deep
// array would overflow the C stack. Real glTF nests well under 20 levels.
constexpr int kMaxJsonDepth = 256;
// After flattening instances: 64 Mi vertices (2 GiB of Vertex) and 256 Mi indices (1 GiB). An
// accessor without a buffer view costs nothing in the file, so its count needs a cap of its own.
constexpr std::size_t kMaxVertices = std::size_t{1} << 26;
constexpr std::size_t kMaxIndices = std::size_t{1} << 28;
// Decoded base-colour textures, all together: 256 Mi texels (1 GiB of RGBA8).
constexpr int kMaxImageSide = 16384;
constexpr std::uint64_t kMaxImageTexels = std::uint64_t{1} << 28;

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kGlbChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kGlbChunkBin = 0x004E4942;   // "BIN\0"

// --- Messages ------------------------------------------------------------------------------------

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// A piece of text fit for a one-line message: control characters become spaces, and long text
// (a data URI echoed by tinygltf, say) is cut short.
std::string clip(std::string_view s, std::size_t maxChars = 400) {
    std::string out;
    for (char c : s.substr(0, maxChars)) out += (static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
    if (s.size() > maxChars) out += "...";
    return out;
}

// tinygltf reports one problem per line, sometimes a million of them. A SceneError or a warning is
// one line, so keep the first few and say how many more there were.
std::string oneLine(std::string_view text, std::size_t maxLines = 3) {
    std::string out;
    std::size_t kept = 0, dropped = 0, pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = trim(text.substr(pos, end - pos));
        pos = end + 1;
        if (line.empty()) continue;
        if (kept < maxLines) {
            if (kept > 0) out += "; ";
            out += clip(line);
            ++kept;
        } else {
            ++dropped;
        }
    }
    if (dropped > 0) out += " (and " + std::to_string(dropped) + " more)";
    return out;
}

[[noreturn]] void fail(const std::string& path, const std::string& fault) {
    throw SceneError(path + ": " + oneLine(fault, 1));
}

// "meshes[2] 'Body'": an index always, the name when there is one.
std::string named(const char* kind, std::size_t index, const std::string& name) {
    std::string s = std::string(kind) + "[" + std::to_string(index) + "]";
    if (!name.empty()) s += " '" + clip(name, 60) + "'";
    return s;
}

std::string counted(std::size_t n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }
bool contains(std::string_view s, std::string_view part) { return s.find(part) != std::string_view::npos; }

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// --- Files ---------------------------------------------------------------------------------------

// Reads a whole regular file. Devices, FIFOs and directories are refused: a glTF uri can name any
// path, and /dev/zero or a FIFO would never end.
bool readRegularFile(const std::string& file, std::vector<unsigned char>& out, std::string& why) {
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (status.type() == fs::file_type::not_found) {
        why = "not found";
        return false;
    }
    if (ec) {
        why = "cannot access (" + ec.message() + ")";
        return false;
    }
    if (!fs::is_regular_file(status)) {
        why = "not a regular file";
        return false;
    }
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec) {
        why = "cannot read (" + ec.message() + ")";
        return false;
    }
    if (size > kMaxFileBytes) {
        why = "too large (" + std::to_string(size) + " bytes; the limit is 2 GiB)";
        return false;
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        why = "cannot open (" + std::string(std::strerror(errno)) + ")";
        return false;
    }
    out.resize(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) {
        why = "cannot read (short read)";
        return false;
    }
    return true;
}

// --- GLB container -------------------------------------------------------------------------------

std::uint32_t readU32(const unsigned char* p) {
    return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24;
}

struct GlbLayout {
    std::size_t jsonOffset = 0;
    std::size_t jsonSize = 0;
    std::size_t length = 0;  // bytes of the container, as its header states
};

// Checks the GLB header and chunk table before tinygltf reads them, so each fault gets its own
// message (tinygltf 2.7 says "Invalid glTF binary." for most of them).
GlbLayout checkGlbContainer(const std::string& path, const std::vector<unsigned char>& bytes) {
    const std::size_t size = bytes.size();
    if (size < 12) fail(path, "GLB header truncated: the file has " + std::to_string(size) + " bytes, the header needs 12");
    const unsigned char* p = bytes.data();
    if (readU32(p) != kGlbMagic) fail(path, "bad GLB magic (the file does not start with 'glTF')");
    const std::uint32_t version = readU32(p + 4);
    if (version != 2) fail(path, "unsupported GLB version " + std::to_string(version) + " (expected 2)");
    const std::size_t length = readU32(p + 8);
    if (length > size)
        fail(path, "GLB length field says " + std::to_string(length) + " bytes, past the end of the file (" +
                       std::to_string(size) + " bytes)");
    if (length < 20) fail(path, "GLB too short (" + std::to_string(length) + " bytes) for its JSON chunk header");
    const std::size_t jsonSize = readU32(p + 12);
    if (readU32(p + 16) != kGlbChunkJson) fail(path, "the first GLB chunk is not the JSON chunk");
    if (jsonSize > length - 20)
        fail(path, "GLB JSON chunk length " + std::to_string(jsonSize) + " runs past the end of the file (" +
                       std::to_string(length - 20) + " bytes follow the chunk header)");
    if (jsonSize == 0) fail(path, "GLB JSON chunk is empty");

    const std::size_t binHeader = 20 + jsonSize;
    const std::size_t rest = length - binHeader;
    if (rest > 0) {
        if (rest < 8) fail(path, "GLB BIN chunk header truncated (" + std::to_string(rest) + " bytes left)");
        const std::size_t binSize = readU32(p + binHeader);
        if (readU32(p + binHeader + 4) != kGlbChunkBin) fail(path, "the second GLB chunk is not a BIN chunk");
        if (binSize > rest - 8)
            fail(path, "GLB BIN chunk length " + std::to_string(binSize) + " runs past the end of the file (" +
                           std::to_string(rest - 8) + " bytes follow the chunk header)");
        // tinygltf refuses these two; say so in plain words first.
        if (binSize == 0) fail(path, "GLB BIN chunk is empty");
        if (binSize % 4 != 0) fail(path, "GLB BIN chunk length " + std::to_string(binSize) + " is not a multiple of 4");
    }
    return {20, jsonSize, length};
}

// --- JSON text -----------------------------------------------------------------------------------

// Checks the JSON text before tinygltf parses it: the root must be an object, and nesting must be
// shallow enough for tinygltf's recursive conversion of extras (see kMaxJsonDepth). Malformed
// JSON is left to the parser, which says where.
void checkJsonText(const std::string& path, const char* text, std::size_t size) {
    std::size_t i = 0;
    if (size >= 3 && std::memcmp(text, "\xEF\xBB\xBF", 3) == 0) i = 3;  // UTF-8 byte order mark
    while (i < size && std::strchr(" \t\r\n", text[i]) != nullptr && text[i] != '\0') ++i;
    if (i == size) fail(path, "malformed JSON: the JSON text is empty");
    const char first = text[i];
    if (first != '{' && first != '\0' && std::strchr("[\"-0123456789tfn", first) != nullptr)
        fail(path, "JSON root is not an object (a glTF file is one JSON object)");

    int depth = 0;
    bool inString = false;
    for (; i < size; ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;  // skip the escaped character
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxJsonDepth)
                fail(path, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
}

// --- tinygltf ------------------------------------------------------------------------------------

// What the tinygltf callbacks need to know.
struct TinyGltfIo {
    std::string baseDir;                     // the glTF file's directory, where uris resolve
    const tinygltf::Model* model = nullptr;  // being filled; buffers come before images
};

bool ioFileExists(const std::string& file, void* user) {
    const auto* io = static_cast<const TinyGltfIo*>(user);
    // tinygltf also tries "./<uri>" in the process's working directory; only the glTF file's own
    // directory counts here, so an unrelated file cannot stand in for a missing one.
    const std::string& dir = io->baseDir;
    if (!startsWith(file, dir.back() == '/' ? dir : dir + "/")) return false;
    std::error_code ec;
    return fs::is_regular_file(file, ec);
}

std::string ioExpandFilePath(const std::string& file, void*) { return file; }

bool ioReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& file, void*) {
    std::string why;
    if (readRegularFile(file, *out, why)) return true;
    if (err) *err += why;
    return false;
}

bool ioWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not supported";
    return false;
}

// tinygltf would decode every image with stb and fail the whole load on one it cannot decode.
// Instead the encoded bytes are kept; only base-colour images are decoded later, and one that
// fails becomes a white texel with a warning.
bool keepEncodedImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
    const auto* io = static_cast<const TinyGltfIo*>(user);
    if (image->bufferView >= 0) {
        // tinygltf 2.7 passes the buffer's bytes at the view's offset without checking the view
        // against the buffer; check before reading any of them.
        const auto& views = io->model->bufferViews;
        const auto& buffers = io->model->buffers;
        const std::size_t v = static_cast<std::size_t>(image->bufferView);
        const bool viewOk = v < views.size() && views[v].buffer >= 0 &&
                            static_cast<std::size_t>(views[v].buffer) < buffers.size();
        const std::size_t bufferSize = viewOk ? buffers[static_cast<std::size_t>(views[v].buffer)].data.size() : 0;
        if (!viewOk || views[v].byteOffset > bufferSize || views[v].byteLength > bufferSize - views[v].byteOffset) {
            if (err)
                *err += "images[" + std::to_string(index) + "]: bufferViews[" + std::to_string(v) +
                        "] overruns its buffer\n";
            return false;
        }
    }
    image->image.clear();
    if (bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;  // the bytes are encoded (PNG, JPEG...), not pixels
    return true;
}

// tinygltf's failures, reworded where its message would not say what is wrong with the file.
std::string describeTinyGltfFailure(const std::string& err, const tinygltf::Model& partial) {
    const std::string line = oneLine(err, 2);
    if (contains(err, "[json.exception.")) return "malformed JSON: " + line;
    if (contains(err, "Root element is not a JSON object")) return "JSON root is not an object";
    // Buffers are parsed in order, so the failing one is the next after those already parsed.
    const std::string buffer = "buffers[" + std::to_string(partial.buffers.size()) + "]";
    if (startsWith(err, "File not found : "))
        return buffer + ": missing external buffer file '" + clip(trim(oneLine(err.substr(17), 1)), 200) + "' (not found)";
    if (startsWith(err, "File read error : ")) return buffer + ": cannot read external buffer file: " + clip(err.substr(18));
    if (startsWith(err, "File size mismatch : ")) return buffer + ": external buffer file size does not match byteLength: " + line;
    if (contains(err, "Failed to decode 'uri'") && contains(err, "in Buffer"))
        return buffer + ": data URI is not valid base64 or does not hold byteLength bytes";
    if (contains(err, "Failed to decode 'uri' for image"))
        return "data URI of an image is not valid base64 (" + line + ")";
    return "glTF parse error: " + line;
}

struct Parsed {
    tinygltf::Model model;
    std::string tinygltfWarnings;  // non-fatal messages, on one line
};

Parsed parseWithTinyGltf(const std::string& path, const std::vector<unsigned char>& bytes, bool binary) {
    Parsed parsed;
    TinyGltfIo io;
    const fs::path parent = fs::path(path).parent_path();
    io.baseDir = parent.empty() ? std::string(".") : parent.string();
    io.model = &parsed.model;

    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&ioFileExists, &ioExpandFilePath, &ioReadWholeFile, &ioWriteWholeFile, &io});
    loader.SetImageLoader(&keepEncodedImage, &io);

    std::string err, warn;
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&parsed.model, &err, &warn, bytes.data(),
                                                   static_cast<unsigned int>(bytes.size()), io.baseDir)
                    : loader.LoadASCIIFromString(&parsed.model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                 static_cast<unsigned int>(bytes.size()), io.baseDir);
    } catch (const std::exception& e) {
        // tinygltf 2.7 can throw from inside (a GLB buffer with byteLength 0 reaches
        // std::vector::at on an empty vector); that is still a fault of the file.
        fail(path, "glTF parse error (tinygltf threw: " + std::string(e.what()) + ")");
    }
    if (!ok) fail(path, describeTinyGltfFailure(err, parsed.model));
    // On success tinygltf may still have written to err: problems it stepped over (a primitive
    // without attributes is dropped, for one). Those are warnings here.
    std::string notes = oneLine(err);
    const std::string warned = oneLine(warn);
    if (!notes.empty() && !warned.empty()) notes += "; ";
    parsed.tinygltfWarnings = notes + warned;
    return parsed;
}

// --- Checks tinygltf does not make ---------------------------------------------------------------

void checkAssetVersion(const std::string& path, const tinygltf::Model& model) {
    const std::string& v = model.asset.version;
    if (!startsWith(v, "2.")) fail(path, "glTF version '" + clip(v, 20) + "' is not supported (only 2.x)");
}

// Compressed geometry cannot be read without its extension: the accessors it replaces are empty.
void checkRequiredExtensions(const std::string& path, const tinygltf::Model& model) {
    for (const std::string& ext : model.extensionsRequired)
        if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression")
            fail(path, "requires extension " + ext + " (compressed geometry), which is not supported");
}

// tinygltf's base64 decoder stops quietly at the first character outside the alphabet, so a
// corrupted data URI can load as truncated or shifted data: insist on clean base64.
bool isCleanBase64(std::string_view s) {
    if (s.size() % 4 == 1) return false;
    std::size_t padding = 0;
    for (char c : s) {
        if (c == '=') {
            ++padding;
        } else if (padding > 0 || !(std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/')) {
            return false;
        }
    }
    return padding == 0 || (padding <= 2 && s.size() % 4 == 0);
}

void checkBufferDataUris(const std::string& path, const tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.buffers.size(); ++i) {
        const std::string& uri = model.buffers[i].uri;
        if (!startsWith(uri, "data:")) continue;
        const std::size_t comma = uri.find(',');
        const bool base64 = comma != std::string::npos && contains(std::string_view(uri).substr(0, comma), ";base64");
        if (!base64 || !isCleanBase64(std::string_view(uri).substr(comma + 1)))
            fail(path, named("buffers", i, model.buffers[i].name) + ": data URI is not valid base64");
    }
}

// Every buffer view must lie inside its buffer; accessors are then checked against their view.
void checkBufferViews(const std::string& path, const tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        const tinygltf::BufferView& view = model.bufferViews[i];
        const std::string what = named("bufferViews", i, view.name);
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
            fail(path, what + ": buffer index " + std::to_string(view.buffer) + " out of range (" +
                           std::to_string(model.buffers.size()) + " buffers)");
        const std::size_t size = model.buffers[static_cast<std::size_t>(view.buffer)].data.size();
        if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
            fail(path, what + ": byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
                           std::to_string(view.byteLength) + " overruns buffers[" + std::to_string(view.buffer) +
                           "] (" + std::to_string(size) + " bytes)");
    }
}

// --- Accessors -----------------------------------------------------------------------------------

// What an accessor is read for, so that a message can say which mesh it belongs to.
struct Use {
    const char* attribute;  // "POSITION", "NORMAL", "TEXCOORD_0", "indices"
    int mesh;
    int primitive;
};

std::string describe(const tinygltf::Model& model, int accessor, const Use& use) {
    std::string s = "accessors[" + std::to_string(accessor) + "]";
    const auto& mesh = model.meshes[static_cast<std::size_t>(use.mesh)];
    return s + " (" + use.attribute + " of " + named("meshes", static_cast<std::size_t>(use.mesh), mesh.name) +
           " primitive " + std::to_string(use.primitive) + ")";
}

std::size_t componentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;  // DOUBLE is tinygltf's, not glTF 2.0's
    }
}

std::size_t componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

std::string typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "type " + std::to_string(type);
    }
}

std::string componentTypeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        default: return std::to_string(componentType);
    }
}

bool isOneOf(int value, std::initializer_list<int> options) {
    return std::find(options.begin(), options.end(), value) != options.end();
}

// The formats glTF 2.0 allows for each use; KHR_mesh_quantization widens those of vertex data.
struct Format {
    int type;
    const char* expected;  // for messages
    bool (*allows)(const tinygltf::Accessor&, bool quantized);
};

const Format kPositionFormat{TINYGLTF_TYPE_VEC3, "VEC3 FLOAT", [](const tinygltf::Accessor& a, bool quantized) {
                                 return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                        (quantized && isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_BYTE,
                                                                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                                                TINYGLTF_COMPONENT_TYPE_SHORT,
                                                                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}));
                             }};
const Format kNormalFormat{TINYGLTF_TYPE_VEC3, "VEC3 FLOAT", [](const tinygltf::Accessor& a, bool quantized) {
                               return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                      (quantized && a.normalized &&
                                       isOneOf(a.componentType,
                                               {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT}));
                           }};
const Format kTexcoordFormat{
    TINYGLTF_TYPE_VEC2, "VEC2 FLOAT, or normalized UNSIGNED_BYTE or UNSIGNED_SHORT",
    [](const tinygltf::Accessor& a, bool quantized) {
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) return true;
        const bool unsignedType = isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
        const bool signedType =
            isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT});
        return (unsignedType && a.normalized) || (quantized && (unsignedType || signedType));
    }};
const Format kIndexFormat{TINYGLTF_TYPE_SCALAR, "SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT",
                          [](const tinygltf::Accessor& a, bool) {
                              return isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
                          }};

// offset + stride * (count - 1) + elementSize <= limit, without overflow. count >= 1.
bool elementsFit(std::size_t offset, std::size_t stride, std::size_t count, std::size_t elementSize,
                 std::size_t limit) {
    if (offset > limit || elementSize > limit - offset) return false;
    const std::size_t room = limit - offset - elementSize;
    return count - 1 == 0 || (stride != 0 && count - 1 <= room / stride);
}

float componentToFloat(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0f : float(p[0]);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const auto v = static_cast<std::int8_t>(p[0]);
            return normalized ? std::max(v / 127.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0f : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0f, -1.0f) : float(v);
        }
        default: return 0.0f;  // excluded by the format checks
    }
}

std::uint32_t componentToIndex(const unsigned char* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        default: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
    }
}

// Reads accessors for one file: every index and byte range is checked before it is used.
class AccessorReader {
public:
    AccessorReader(const std::string& path, const tinygltf::Model& model, bool quantized)
        : path_(path), model_(model), quantized_(quantized) {}

    // count * components floats, after integer normalisation and sparse substitution.
    // maxCount bounds the allocation for accessors whose elements are not in the file.
    std::vector<float> floats(int index, const Use& use, const Format& format, std::size_t maxCount) const {
        const tinygltf::Accessor& a = checked(index, use, format, maxCount);
        const std::size_t n = componentCount(a.type), bytes = componentBytes(a.componentType);
        std::vector<float> out(a.count * n, 0.0f);
        const auto readElement = [&](std::size_t i, const unsigned char* p) {
            for (std::size_t c = 0; c < n; ++c) out[i * n + c] = componentToFloat(p + c * bytes, a.componentType, a.normalized);
        };
        forEachElement(index, a, use, readElement);
        return out;
    }

    std::vector<std::uint32_t> indices(int index, const Use& use, std::size_t maxCount) const {
        const tinygltf::Accessor& a = checked(index, use, kIndexFormat, maxCount);
        std::vector<std::uint32_t> out(a.count, 0);
        forEachElement(index, a, use, [&](std::size_t i, const unsigned char* p) { out[i] = componentToIndex(p, a.componentType); });
        return out;
    }

    std::size_t count(int index) const { return model_.accessors[static_cast<std::size_t>(index)].count; }

private:
    [[noreturn]] void failAt(int index, const Use& use, const std::string& fault) const {
        fail(path_, describe(model_, index, use) + ": " + fault);
    }

    const tinygltf::Accessor& checked(int index, const Use& use, const Format& format, std::size_t maxCount) const {
        const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];  // index checked by the plan
        if (a.type != format.type || !format.allows(a, quantized_))
            failAt(index, use,
                   "type " + typeName(a.type) + " with componentType " + componentTypeName(a.componentType) +
                       (a.normalized ? " (normalized)" : "") + " is not valid for " + use.attribute + " (expected " +
                       format.expected + ")");
        // Elements in a buffer view are bounded by the file; check that first, as the real fault.
        if (a.bufferView >= 0 && a.count > 0) {
            const unsigned char* base = nullptr;
            std::size_t stride = 0;
            locate(index, a, use, componentBytes(a.componentType) * componentCount(a.type), base, stride);
        }
        if (a.count > maxCount)
            failAt(index, use, "count " + std::to_string(a.count) + " is over the limit (" + std::to_string(maxCount) + ")");
        return a;
    }

    // Calls fn(i, bytes of element i) for every element in the buffer view, then for every sparse
    // substitute. Elements of an accessor without a buffer view are zeros and are not visited.
    template <class Fn>
    void forEachElement(int index, const tinygltf::Accessor& a, const Use& use, Fn fn) const {
        const std::size_t elementSize = componentBytes(a.componentType) * componentCount(a.type);
        if (a.count > 0 && a.bufferView >= 0) {
            const unsigned char* base = nullptr;
            std::size_t stride = 0;
            locate(index, a, use, elementSize, base, stride);
            for (std::size_t i = 0; i < a.count; ++i) fn(i, base + i * stride);
        }
        if (a.sparse.isSparse) forEachSparse(index, a, use, elementSize, fn);
    }

    void locate(int index, const tinygltf::Accessor& a, const Use& use, std::size_t elementSize,
                const unsigned char*& base, std::size_t& stride) const {
        const tinygltf::BufferView& view = viewOf(index, use, a.bufferView, "bufferView");
        if (view.byteStride != 0 && view.byteStride < elementSize)
            failAt(index, use, "byteStride " + std::to_string(view.byteStride) + " of bufferViews[" +
                                   std::to_string(a.bufferView) + "] is smaller than an element (" +
                                   std::to_string(elementSize) + " bytes)");
        stride = view.byteStride != 0 ? view.byteStride : elementSize;
        if (!elementsFit(a.byteOffset, stride, a.count, elementSize, view.byteLength))
            failAt(index, use, "byteOffset " + std::to_string(a.byteOffset) + " + byteStride " + std::to_string(stride) +
                                   " * (count " + std::to_string(a.count) + " - 1) + element size " +
                                   std::to_string(elementSize) + " overruns bufferViews[" +
                                   std::to_string(a.bufferView) + "] (" + std::to_string(view.byteLength) + " bytes)");
        base = bufferBytes(view) + a.byteOffset;
    }

    template <class Fn>
    void forEachSparse(int index, const tinygltf::Accessor& a, const Use& use, std::size_t elementSize, Fn fn) const {
        const auto& sparse = a.sparse;
        if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > a.count)
            failAt(index, use, "sparse count " + std::to_string(sparse.count) + " is out of range (1.." +
                                   std::to_string(a.count) + ")");
        const std::size_t n = static_cast<std::size_t>(sparse.count);
        const int indexType = sparse.indices.componentType;
        if (!isOneOf(indexType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}))
            failAt(index, use, "sparse indices componentType " + componentTypeName(indexType) + " is not unsigned");
        const std::size_t indexSize = componentBytes(indexType);
        const unsigned char* indices = sparseBytes(index, use, sparse.indices.bufferView, sparse.indices.byteOffset,
                                                   n, indexSize, "sparse indices");
        const unsigned char* values = sparseBytes(index, use, sparse.values.bufferView, sparse.values.byteOffset, n,
                                                  elementSize, "sparse values");
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t target = componentToIndex(indices + k * indexSize, indexType);
            if (target >= a.count)
                failAt(index, use, "sparse index " + std::to_string(target) + " is out of range (count " +
                                       std::to_string(a.count) + ")");
            fn(target, values + k * elementSize);
        }
    }

    // Sparse indices and values are tightly packed (the spec forbids a stride on their views).
    const unsigned char* sparseBytes(int index, const Use& use, int viewIndex, int byteOffset, std::size_t count,
                                     std::size_t elementSize, const char* what) const {
        const tinygltf::BufferView& view = viewOf(index, use, viewIndex, what);
        if (byteOffset < 0 || !elementsFit(static_cast<std::size_t>(byteOffset), elementSize, count, elementSize, view.byteLength))
            failAt(index, use, std::string(what) + " (byteOffset " + std::to_string(byteOffset) + ", " +
                                   std::to_string(count) + " x " + std::to_string(elementSize) +
                                   " bytes) overrun bufferViews[" + std::to_string(viewIndex) + "] (" +
                                   std::to_string(view.byteLength) + " bytes)");
        return bufferBytes(view) + byteOffset;
    }

    const tinygltf::BufferView& viewOf(int index, const Use& use, int viewIndex, const char* what) const {
        if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model_.bufferViews.size())
            failAt(index, use, std::string(what) + " index " + std::to_string(viewIndex) + " out of range (" +
                                   std::to_string(model_.bufferViews.size()) + " buffer views)");
        return model_.bufferViews[static_cast<std::size_t>(viewIndex)];
    }

    // Views were checked against their buffers by checkBufferViews.
    const unsigned char* bufferBytes(const tinygltf::BufferView& view) const {
        return model_.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset;
    }

    const std::string& path_;
    const tinygltf::Model& model_;
    bool quantized_;
};

// --- Node hierarchy ------------------------------------------------------------------------------

glm::dmat4 localTransform(const std::string& path, const tinygltf::Node& node, std::size_t index) {
    const auto badLength = [&](const char* what, std::size_t got, const char* expected) {
        fail(path, named("nodes", index, node.name) + ": " + what + " has " + std::to_string(got) +
                       " numbers, expected " + expected);
    };
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) badLength("matrix", node.matrix.size(), "16");
        return glm::make_mat4(node.matrix.data());  // glTF and glm are both column-major
    }
    if (!node.translation.empty() && node.translation.size() != 3) badLength("translation", node.translation.size(), "3");
    if (!node.rotation.empty() && node.rotation.size() != 4) badLength("rotation", node.rotation.size(), "4");
    if (!node.scale.empty() && node.scale.size() != 3) badLength("scale", node.scale.size(), "3");

    glm::dmat4 m(1.0);
    if (!node.translation.empty()) m = glm::translate(m, glm::make_vec3(node.translation.data()));
    if (!node.rotation.empty()) {
        const auto& r = node.rotation;  // glTF stores x, y, z, w
        const glm::dquat q(r[3], r[0], r[1], r[2]);
        const double length = glm::length(q);
        if (!(length > 0.0) || !std::isfinite(length))
            fail(path, named("nodes", index, node.name) + ": rotation quaternion has zero or non-finite length");
        m *= glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) m = glm::scale(m, glm::make_vec3(node.scale.data()));
    return m;
}

struct MeshInstance {
    std::size_t node;
    std::size_t mesh;
    glm::dmat4 world;
};

// The default scene's mesh instances with their world transforms. Nodes are walked with an
// explicit stack (a 100,000-deep chain must not recurse), and each node may be entered once:
// glTF nodes form disjoint trees, and re-entering would loop on a cycle or multiply a shared
// subtree exponentially.
std::vector<MeshInstance> flattenNodes(const std::string& path, const tinygltf::Model& model) {
    if (model.scenes.empty()) fail(path, "no scene: the file defines no scenes");
    std::size_t sceneIndex = 0;
    if (model.defaultScene >= 0) {
        sceneIndex = static_cast<std::size_t>(model.defaultScene);
        if (sceneIndex >= model.scenes.size())
            fail(path, "scene index " + std::to_string(sceneIndex) + " out of range (" +
                           std::to_string(model.scenes.size()) + " scenes)");
    }
    const tinygltf::Scene& scene = model.scenes[sceneIndex];
    const std::string sceneName = named("scenes", sceneIndex, scene.name);
    if (scene.nodes.empty()) fail(path, sceneName + " is empty: it lists no nodes");

    const std::size_t nodeCount = model.nodes.size();
    enum class Mark : std::uint8_t { unvisited, onPath, done };
    std::vector<Mark> marks(nodeCount, Mark::unvisited);
    std::vector<glm::dmat4> world(nodeCount);
    struct Step {
        std::size_t node;
        std::ptrdiff_t parent;  // -1 for a scene root
        bool leaving;           // pops the node off the current path
    };
    std::vector<Step> stack;
    const auto push = [&](int child, std::ptrdiff_t parent, const std::string& from) {
        if (child < 0 || static_cast<std::size_t>(child) >= nodeCount)
            fail(path, from + ": node index " + std::to_string(child) + " out of range (" + std::to_string(nodeCount) +
                           " nodes)");
        stack.push_back({static_cast<std::size_t>(child), parent, false});
    };
    for (auto it = scene.nodes.rbegin(); it != scene.nodes.rend(); ++it) push(*it, -1, sceneName);

    std::vector<MeshInstance> instances;
    while (!stack.empty()) {
        const Step step = stack.back();
        stack.pop_back();
        if (step.leaving) {
            marks[step.node] = Mark::done;
            continue;
        }
        const tinygltf::Node& node = model.nodes[step.node];
        const std::string name = named("nodes", step.node, node.name);
        if (marks[step.node] == Mark::onPath) fail(path, "node cycle: " + name + " is its own ancestor");
        if (marks[step.node] == Mark::done)
            fail(path, name + " is reached twice (more than one parent, or listed twice); glTF nodes must form trees");
        marks[step.node] = Mark::onPath;

        const glm::dmat4 parentWorld = step.parent < 0 ? glm::dmat4(1.0) : world[static_cast<std::size_t>(step.parent)];
        world[step.node] = parentWorld * localTransform(path, node, step.node);
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
                fail(path, name + ": mesh index " + std::to_string(node.mesh) + " out of range (" +
                               std::to_string(model.meshes.size()) + " meshes)");
            instances.push_back({step.node, static_cast<std::size_t>(node.mesh), world[step.node]});
        }
        stack.push_back({step.node, step.parent, true});
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
            push(*it, static_cast<std::ptrdiff_t>(step.node), name);
    }
    return instances;
}

// --- Meshes --------------------------------------------------------------------------------------

// Counts of what was skipped or repaired, each reported once as a warning.
struct Skipped {
    std::map<int, std::size_t> primitiveModes;  // mode -> primitives
    std::size_t withoutPosition = 0;
    std::size_t emptyPrimitives = 0;
    std::size_t morphedMeshes = 0;
    std::size_t vertexColours = 0;
    std::size_t regeneratedNormals = 0;  // primitives whose NORMAL held NaN or infinity
    std::size_t repairedTexcoords = 0;
    std::size_t baseColorOnOtherTexcoord = 0;
    std::size_t texturesWithoutSource = 0;
    std::vector<std::string> failedImages;
};

// Primitives that share their vertex attributes (one big vertex buffer drawn in several material
// runs) share one block of vertices per instance rather than each copying all of it.
struct VertexGroup {
    int position = -1, normal = -1, texcoord = -1;  // accessors; -1 where absent
    int firstPrimitive = 0;                          // names the group in messages
};

struct PrimitivePlan {
    int primitive;
    std::size_t group;
    int indices;   // accessor, or -1
    int material;  // glTF material, or -1
};

// How one glTF mesh becomes triangles, worked out once however many nodes instance it, so that a
// mesh with a million empty primitives costs one pass, not one per instance.
struct MeshPlan {
    std::vector<VertexGroup> groups;
    std::vector<PrimitivePlan> primitives;
};

MeshPlan planMesh(const std::string& path, const tinygltf::Model& model, std::size_t meshIndex, Skipped& skipped) {
    const tinygltf::Mesh& mesh = model.meshes[meshIndex];
    MeshPlan plan;
    std::map<std::tuple<int, int, int>, std::size_t> groupOf;
    bool morphed = false;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        // Built only for a message: a mesh may have a million primitives.
        const auto where = [&] { return named("meshes", meshIndex, mesh.name) + " primitive " + std::to_string(p); };
        morphed = morphed || !prim.targets.empty();
        if (prim.mode != TINYGLTF_MODE_TRIANGLES) {
            ++skipped.primitiveModes[prim.mode];
            continue;
        }
        const auto attribute = [&](const char* name) {
            const auto it = prim.attributes.find(name);
            if (it == prim.attributes.end()) return -1;
            if (it->second < 0 || static_cast<std::size_t>(it->second) >= model.accessors.size())
                fail(path, where() + ": " + name + " accessor index " + std::to_string(it->second) + " out of range (" +
                               std::to_string(model.accessors.size()) + " accessors)");
            return it->second;
        };
        const int position = attribute("POSITION");
        if (position < 0) {
            ++skipped.withoutPosition;
            continue;
        }
        const int normal = attribute("NORMAL");
        const int texcoord = attribute("TEXCOORD_0");
        if (prim.attributes.count("COLOR_0") != 0) ++skipped.vertexColours;
        if (prim.indices >= 0 && static_cast<std::size_t>(prim.indices) >= model.accessors.size())
            fail(path, where() + ": indices accessor index " + std::to_string(prim.indices) + " out of range (" +
                           std::to_string(model.accessors.size()) + " accessors)");
        if (prim.material >= 0 && static_cast<std::size_t>(prim.material) >= model.materials.size())
            fail(path, where() + ": material index " + std::to_string(prim.material) + " out of range (" +
                           std::to_string(model.materials.size()) + " materials)");

        const auto key = std::make_tuple(position, normal, texcoord);
        auto [it, added] = groupOf.try_emplace(key, plan.groups.size());
        if (added) plan.groups.push_back({position, normal, texcoord, static_cast<int>(p)});
        plan.primitives.push_back({static_cast<int>(p), it->second, prim.indices, prim.material});
    }
    if (morphed) ++skipped.morphedMeshes;
    return plan;
}

glm::vec3 safeNormalize(const glm::vec3& v) {
    const float length = glm::length(v);
    if (!(length > 0.0f) || !std::isfinite(length)) return glm::vec3(0.0f, 1.0f, 0.0f);
    return v / length;
}

// Builds the scene from mesh instances: vertices in world space, materials and images on first use.
class SceneBuilder {
public:
    SceneBuilder(const std::string& path, const tinygltf::Model& model, Scene& scene, Skipped& skipped)
        : path_(path),
          model_(model),
          scene_(scene),
          skipped_(skipped),
          reader_(path, model, std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                         "KHR_mesh_quantization") != model.extensionsUsed.end()),
          materialSlots_(model.materials.size(), -1),
          imageSlots_(model.images.size(), -1) {}

    void addInstance(const MeshInstance& instance, const MeshPlan& plan);

    // One draw range per material (instances append in node order, so a material recurs).
    void finish();

private:
    struct Block {
        std::uint32_t base = 0;
        std::uint32_t count = 0;
        bool generateNormals = false;
    };

    Block appendVertices(const MeshInstance& instance, const VertexGroup& group, const glm::dmat3& normalMatrix);
    void appendTriangles(const MeshInstance& instance, const PrimitivePlan& prim, const Block& block, bool mirrored);
    void generateNormals(const Block& block, const std::vector<std::pair<std::size_t, std::size_t>>& ranges);
    std::uint32_t materialFor(int gltfMaterial);
    Material convertMaterial(std::size_t index);
    int imageFor(std::size_t index);

    const std::string& path_;
    const tinygltf::Model& model_;
    Scene& scene_;
    Skipped& skipped_;
    AccessorReader reader_;
    std::vector<int> materialSlots_;  // glTF material -> Scene::materials index
    std::vector<int> imageSlots_;     // glTF image -> Scene::images index
    std::optional<std::uint32_t> defaultMaterial_;
    std::vector<DrawRange> runs_;  // per primitive instance, before grouping
    std::uint64_t texelBudget_ = kMaxImageTexels;
};

void SceneBuilder::addInstance(const MeshInstance& instance, const MeshPlan& plan) {
    // Normals transform by the inverse transpose of the linear part. Its columns are the cross
    // products of the matrix's columns over the determinant; dropping the division keeps the
    // directions and still works for singular transforms (a zero scale), keeping only the sign.
    const glm::dmat3 linear(instance.world);
    const double det = glm::determinant(linear);
    glm::dmat3 normalMatrix(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                            glm::cross(linear[0], linear[1]));
    // A mirroring transform flips triangle winding; glTF says to flip it back so that front faces
    // stay front faces (counter-clockwise).
    const bool mirrored = det < 0.0;
    if (mirrored) normalMatrix = -normalMatrix;

    std::vector<Block> blocks;
    blocks.reserve(plan.groups.size());
    for (const VertexGroup& group : plan.groups) blocks.push_back(appendVertices(instance, group, normalMatrix));

    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> generated(plan.groups.size());
    for (const PrimitivePlan& prim : plan.primitives) {
        const Block& block = blocks[prim.group];
        const std::size_t first = scene_.indices.size();
        appendTriangles(instance, prim, block, mirrored);
        const std::size_t count = scene_.indices.size() - first;
        if (count == 0) {
            ++skipped_.emptyPrimitives;
            continue;
        }
        runs_.push_back({static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(count), materialFor(prim.material)});
        if (block.generateNormals) generated[prim.group].emplace_back(first, count);
    }
    for (std::size_t g = 0; g < blocks.size(); ++g)
        if (blocks[g].generateNormals) generateNormals(blocks[g], generated[g]);
}

SceneBuilder::Block SceneBuilder::appendVertices(const MeshInstance& instance, const VertexGroup& group,
                                                 const glm::dmat3& normalMatrix) {
    const Use positionUse{"POSITION", static_cast<int>(instance.mesh), group.firstPrimitive};
    const std::size_t room = kMaxVertices - scene_.vertices.size();
    const std::vector<float> positions = reader_.floats(group.position, positionUse, kPositionFormat, room);
    const std::size_t count = positions.size() / 3;
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (!std::isfinite(positions[i]))
            fail(path_, describe(model_, group.position, positionUse) + ": non-finite position (NaN or infinity) at element " +
                            std::to_string(i / 3));

    const auto sameCount = [&](int accessor, const Use& use) {
        if (reader_.count(accessor) != count)
            fail(path_, describe(model_, accessor, use) + ": count " + std::to_string(reader_.count(accessor)) +
                            " differs from the POSITION count " + std::to_string(count));
    };
    Block block;
    block.base = static_cast<std::uint32_t>(scene_.vertices.size());
    block.count = static_cast<std::uint32_t>(count);

    std::vector<float> normals;
    if (group.normal >= 0) {
        const Use use{"NORMAL", static_cast<int>(instance.mesh), group.firstPrimitive};
        sameCount(group.normal, use);
        normals = reader_.floats(group.normal, use, kNormalFormat, count);
        // Broken normals are a shading fault, not a geometry one: generate them instead.
        if (!std::all_of(normals.begin(), normals.end(), [](float f) { return std::isfinite(f); })) {
            ++skipped_.regeneratedNormals;
            normals.clear();
        }
    }
    block.generateNormals = normals.empty();

    std::vector<float> uvs;
    if (group.texcoord >= 0) {
        const Use use{"TEXCOORD_0", static_cast<int>(instance.mesh), group.firstPrimitive};
        sameCount(group.texcoord, use);
        uvs = reader_.floats(group.texcoord, use, kTexcoordFormat, count);
        bool repaired = false;
        for (float& f : uvs) {
            if (!std::isfinite(f)) {
                f = 0.0f;
                repaired = true;
            }
        }
        if (repaired) ++skipped_.repairedTexcoords;
    }

    const glm::dmat4& m = instance.world;
    scene_.vertices.reserve(scene_.vertices.size() + count);
    for (std::size_t i = 0; i < count; ++i) {
        Vertex v;
        const glm::dvec4 p = m * glm::dvec4(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 1.0);
        v.position = glm::vec3(p);
        if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z))
            fail(path_, named("nodes", instance.node, model_.nodes[instance.node].name) +
                            ": the node transform makes a position of " +
                            named("meshes", instance.mesh, model_.meshes[instance.mesh].name) + " non-finite");
        if (!normals.empty())
            v.normal = safeNormalize(glm::vec3(normalMatrix * glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2])));
        if (!uvs.empty()) v.uv = glm::vec2(uvs[2 * i], uvs[2 * i + 1]);
        scene_.vertices.push_back(v);
    }
    return block;
}

void SceneBuilder::appendTriangles(const MeshInstance& instance, const PrimitivePlan& prim, const Block& block,
                                   bool mirrored) {
    const Use use{"indices", static_cast<int>(instance.mesh), prim.primitive};
    const auto where = [&] {
        return named("meshes", instance.mesh, model_.meshes[instance.mesh].name) + " primitive " +
               std::to_string(prim.primitive);
    };
    const std::size_t room = kMaxIndices - scene_.indices.size();
    std::vector<std::uint32_t> local;
    if (prim.indices >= 0) {
        local = reader_.indices(prim.indices, use, room);
        for (std::size_t i = 0; i < local.size(); ++i)
            if (local[i] >= block.count)
                fail(path_, describe(model_, prim.indices, use) + ": index " + std::to_string(local[i]) + " at element " +
                                std::to_string(i) + " is out of range (vertex count " + std::to_string(block.count) + ")");
    } else {
        if (block.count > room) fail(path_, where() + ": too many vertices to draw (index limit)");
        local.resize(block.count);
        for (std::uint32_t i = 0; i < block.count; ++i) local[i] = i;
    }
    if (local.size() % 3 != 0) {
        const std::string what = prim.indices >= 0 ? describe(model_, prim.indices, use) : where();
        fail(path_, what + ": " + std::to_string(local.size()) + (prim.indices >= 0 ? " indices" : " vertices") +
                        " do not make whole triangles (not a multiple of 3)");
    }
    for (std::size_t t = 0; t < local.size(); t += 3) {
        scene_.indices.push_back(block.base + local[t]);
        scene_.indices.push_back(block.base + local[t + (mirrored ? 2 : 1)]);
        scene_.indices.push_back(block.base + local[t + (mirrored ? 1 : 2)]);
    }
}

// Per-vertex normals from the triangles that use the vertices, each face weighted by its area
// (the cross product of two edges is twice the area). Positions are already in world space and
// winding already corrected, so the result needs no transform.
void SceneBuilder::generateNormals(const Block& block, const std::vector<std::pair<std::size_t, std::size_t>>& ranges) {
    std::vector<glm::dvec3> sums(block.count, glm::dvec3(0.0));
    for (const auto& [first, count] : ranges) {
        for (std::size_t t = first; t < first + count; t += 3) {
            const std::uint32_t a = scene_.indices[t], b = scene_.indices[t + 1], c = scene_.indices[t + 2];
            const glm::dvec3 pa(scene_.vertices[a].position), pb(scene_.vertices[b].position), pc(scene_.vertices[c].position);
            const glm::dvec3 face = glm::cross(pb - pa, pc - pa);
            sums[a - block.base] += face;
            sums[b - block.base] += face;
            sums[c - block.base] += face;
        }
    }
    for (std::uint32_t i = 0; i < block.count; ++i) scene_.vertices[block.base + i].normal = safeNormalize(glm::vec3(sums[i]));
}

std::uint32_t SceneBuilder::materialFor(int gltfMaterial) {
    if (gltfMaterial < 0) {
        // Primitives without a material are drawn white, as glTF's default material is.
        if (!defaultMaterial_) {
            defaultMaterial_ = static_cast<std::uint32_t>(scene_.materials.size());
            Material white;
            white.name = "default";
            scene_.materials.push_back(white);
        }
        return *defaultMaterial_;
    }
    int& slot = materialSlots_[static_cast<std::size_t>(gltfMaterial)];
    if (slot < 0) {
        Material converted = convertMaterial(static_cast<std::size_t>(gltfMaterial));
        slot = static_cast<int>(scene_.materials.size());
        scene_.materials.push_back(std::move(converted));
    }
    return static_cast<std::uint32_t>(slot);
}

Material SceneBuilder::convertMaterial(std::size_t index) {
    const tinygltf::Material& source = model_.materials[index];
    const std::string what = named("materials", index, source.name);
    Material m;
    m.name = source.name.empty() ? "material " + std::to_string(index) : source.name;
    const std::vector<double>& f = source.pbrMetallicRoughness.baseColorFactor;
    if (f.size() != 4)
        fail(path_, what + ": baseColorFactor has " + std::to_string(f.size()) + " numbers, expected 4");
    // The spec bounds each factor to [0, 1]; clamping keeps a stray value from blowing out shading.
    m.baseColorFactor = glm::clamp(glm::vec4(glm::dvec4(f[0], f[1], f[2], f[3])), 0.0f, 1.0f);
    m.doubleSided = source.doubleSided;
    m.metallic = static_cast<float>(std::clamp(source.pbrMetallicRoughness.metallicFactor, 0.0, 1.0));
    m.roughness = static_cast<float>(std::clamp(source.pbrMetallicRoughness.roughnessFactor, 0.0, 1.0));

    const tinygltf::TextureInfo& info = source.pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) return m;
    if (static_cast<std::size_t>(info.index) >= model_.textures.size())
        fail(path_, what + ": baseColorTexture index " + std::to_string(info.index) + " out of range (" +
                        std::to_string(model_.textures.size()) + " textures)");
    if (info.texCoord != 0) {
        ++skipped_.baseColorOnOtherTexcoord;  // only UV0 is modelled
        return m;
    }
    const int image = model_.textures[static_cast<std::size_t>(info.index)].source;
    if (image < 0) {
        ++skipped_.texturesWithoutSource;  // the image comes through an extension (KTX2, WebP...)
        return m;
    }
    if (static_cast<std::size_t>(image) >= model_.images.size())
        fail(path_, named("textures", static_cast<std::size_t>(info.index), model_.textures[static_cast<std::size_t>(info.index)].name) +
                        ": source image index " + std::to_string(image) + " out of range (" +
                        std::to_string(model_.images.size()) + " images)");
    m.baseColorTexture.image = imageFor(static_cast<std::size_t>(image));
    return m;
}

// Decodes to RGBA8, rows top to bottom (stb's order, as long as no one turns on its vertical
// flip). The colour bytes stay sRGB-encoded, as glTF stores base colour.
bool decodeRgba8(const std::vector<unsigned char>& encoded, Image& out, std::uint64_t& texelBudget, std::string& why) {
    if (encoded.empty()) {
        why = "no image data (external file missing or unreadable)";
        return false;
    }
    const auto failureReason = [] {
        const char* reason = stbi_failure_reason();
        return std::string(reason != nullptr ? reason : "unknown error");
    };
    const int size = static_cast<int>(encoded.size());  // bounded by kMaxFileBytes
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(encoded.data(), size, &w, &h, &channels)) {
        why = "cannot decode: " + failureReason();
        return false;
    }
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) {
        why = "size " + std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." + std::to_string(kMaxImageSide);
        return false;
    }
    const std::uint64_t texels = std::uint64_t(w) * std::uint64_t(h);
    if (texels > texelBudget) {
        why = "textures exceed the limit of " + std::to_string(kMaxImageTexels) + " texels in all";
        return false;
    }
    unsigned char* pixels = stbi_load_from_memory(encoded.data(), size, &w, &h, &channels, 4);
    if (pixels == nullptr) {
        why = "cannot decode: " + failureReason();
        return false;
    }
    out.width = w;
    out.height = h;
    out.rgba8.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 4);
    stbi_image_free(pixels);
    texelBudget -= texels;
    return true;
}

int SceneBuilder::imageFor(std::size_t index) {
    int& slot = imageSlots_[index];
    if (slot >= 0) return slot;
    const tinygltf::Image& source = model_.images[index];
    Image image;
    image.name = !source.name.empty() ? source.name : !source.uri.empty() ? source.uri : "image " + std::to_string(index);
    std::string why;
    if (!decodeRgba8(source.image, image, texelBudget_, why)) {
        // One bad image should not cost the whole scene: a white texel leaves the factor alone.
        skipped_.failedImages.push_back(named("images", index, source.name.empty() ? source.uri : source.name) + " (" +
                                        why + ")");
        image.width = 1;
        image.height = 1;
        image.rgba8 = {255, 255, 255, 255};
    }
    slot = static_cast<int>(scene_.images.size());
    scene_.images.push_back(std::move(image));
    return slot;
}

void SceneBuilder::finish() {
    std::vector<std::size_t> offsets(scene_.materials.size() + 1, 0);
    for (const DrawRange& run : runs_) offsets[run.material + 1] += run.indexCount;
    for (std::size_t m = 1; m < offsets.size(); ++m) offsets[m] += offsets[m - 1];

    std::vector<std::uint32_t> grouped(scene_.indices.size());
    std::vector<std::size_t> cursor(offsets.begin(), offsets.end() - 1);
    for (const DrawRange& run : runs_) {
        std::copy_n(scene_.indices.begin() + run.firstIndex, run.indexCount, grouped.begin() + cursor[run.material]);
        cursor[run.material] += run.indexCount;
    }
    scene_.indices.swap(grouped);
    scene_.draws.clear();
    for (std::size_t m = 0; m + 1 < offsets.size(); ++m)
        if (offsets[m + 1] > offsets[m])
            scene_.draws.push_back({static_cast<std::uint32_t>(offsets[m]),
                                    static_cast<std::uint32_t>(offsets[m + 1] - offsets[m]), static_cast<std::uint32_t>(m)});
}

// --- Warnings ------------------------------------------------------------------------------------

// Extensions this loader reads (or whose absence changes nothing it reads).
bool isHandledExtension(const std::string& name) { return name == "KHR_mesh_quantization"; }

// One line per kind of thing the scene model does not hold.
std::vector<std::string> unmodelledFeatures(const tinygltf::Model& model, const Skipped& skipped) {
    std::vector<std::string> lines;
    const auto note = [&](std::size_t n, const std::string& text) {
        if (n > 0) lines.push_back(text);
    };
    note(model.skins.size(), counted(model.skins.size(), "skin", "skins") + " skipped (not modelled; skinned meshes are drawn unposed)");
    note(model.animations.size(), counted(model.animations.size(), "animation", "animations") + " skipped (not modelled)");
    note(model.cameras.size(), counted(model.cameras.size(), "camera", "cameras") + " skipped (not modelled)");
    note(skipped.morphedMeshes, "morph targets of " + counted(skipped.morphedMeshes, "mesh", "meshes") + " skipped (not modelled)");

    // tinygltf reads KHR_lights_punctual's lights, so those can be counted.
    const bool countedLights = !model.lights.empty();
    if (countedLights)
        lines.push_back(counted(model.lights.size(), "light", "lights") + " (KHR_lights_punctual) skipped (not modelled)");
    for (const std::string& ext : model.extensionsUsed)
        if (!(countedLights && ext == "KHR_lights_punctual") && !isHandledExtension(ext))
            lines.push_back("extension " + clip(ext, 80) + " skipped (not modelled)");

    std::size_t normal = 0, occlusion = 0, emissive = 0, metallicRoughness = 0, alpha = 0, emissiveFactor = 0;
    for (const tinygltf::Material& m : model.materials) {
        normal += m.normalTexture.index >= 0;
        occlusion += m.occlusionTexture.index >= 0;
        emissive += m.emissiveTexture.index >= 0;
        metallicRoughness += m.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0;
        alpha += m.alphaMode != "OPAQUE";
        emissiveFactor += std::any_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), [](double v) { return v != 0.0; });
    }
    if (normal + occlusion + emissive + metallicRoughness > 0) {
        std::string kinds;
        const auto kind = [&](std::size_t n, const char* name) {
            if (n > 0) kinds += std::string(kinds.empty() ? "" : ", ") + name + " x" + std::to_string(n);
        };
        kind(normal, "normal");
        kind(occlusion, "occlusion");
        kind(emissive, "emissive");
        kind(metallicRoughness, "metallicRoughness");
        lines.push_back("textures other than baseColor skipped (not modelled): " + kinds);
    }
    note(skipped.baseColorOnOtherTexcoord, "baseColor textures of " + counted(skipped.baseColorOnOtherTexcoord, "material", "materials") +
                                               " skipped: they use a texCoord other than 0 (only UV0 is modelled)");
    note(skipped.texturesWithoutSource, counted(skipped.texturesWithoutSource, "baseColor texture", "baseColor textures") +
                                            " skipped: no PNG/JPEG source (the image needs an extension)");
    note(alpha, "alphaMode of " + counted(alpha, "material", "materials") + " ignored (not modelled; drawn opaque)");
    note(emissiveFactor, "emissiveFactor of " + counted(emissiveFactor, "material", "materials") + " ignored (not modelled)");

    if (!skipped.primitiveModes.empty()) {
        static const char* const kModeNames[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP", "TRIANGLES",
                                                 "TRIANGLE_STRIP", "TRIANGLE_FAN"};
        std::size_t total = 0;
        std::string modes;
        for (const auto& [mode, n] : skipped.primitiveModes) {
            total += n;
            const std::string name = mode >= 0 && mode < 7 ? kModeNames[mode] : "mode " + std::to_string(mode);
            modes += std::string(modes.empty() ? "" : ", ") + name + " x" + std::to_string(n);
        }
        lines.push_back(counted(total, "primitive", "primitives") + " with a non-triangle mode skipped (only TRIANGLES is modelled): " + modes);
    }
    note(skipped.withoutPosition, counted(skipped.withoutPosition, "primitive", "primitives") + " without POSITION skipped");
    note(skipped.emptyPrimitives, counted(skipped.emptyPrimitives, "empty primitive", "empty primitives") + " skipped (no triangles)");
    note(skipped.vertexColours, "vertex colours (COLOR_0) of " + counted(skipped.vertexColours, "primitive", "primitives") + " ignored (not modelled)");
    note(skipped.regeneratedNormals, "NORMAL of " + counted(skipped.regeneratedNormals, "primitive", "primitives") +
                                         " held NaN or infinity; normals generated instead");
    note(skipped.repairedTexcoords, "TEXCOORD_0 of " + counted(skipped.repairedTexcoords, "primitive", "primitives") +
                                        " held NaN or infinity; those set to 0");
    if (!skipped.failedImages.empty()) {
        std::string list;
        for (std::size_t i = 0; i < skipped.failedImages.size() && i < 3; ++i) list += (i ? "; " : "") + skipped.failedImages[i];
        if (skipped.failedImages.size() > 3) list += "; and " + std::to_string(skipped.failedImages.size() - 3) + " more";
        lines.push_back(counted(skipped.failedImages.size(), "image", "images") +
                        " could not be decoded; a 1x1 white texture stands in: " + list);
    }
    return lines;
}

Scene loadChecked(const std::string& path, std::vector<std::string>& warnings) {
    const std::string ext = lowerExtension(path);
    if (ext != ".gltf" && ext != ".glb") fail(path, "not a glTF file (expected a .gltf or .glb extension)");
    const bool binary = ext == ".glb";

    std::vector<unsigned char> bytes;
    std::string why;
    if (!readRegularFile(path, bytes, why)) fail(path, "cannot open glTF file: " + why);
    if (binary) {
        const GlbLayout glb = checkGlbContainer(path, bytes);
        checkJsonText(path, reinterpret_cast<const char*>(bytes.data() + glb.jsonOffset), glb.jsonSize);
        bytes.resize(glb.length);  // bytes past the stated length are not part of the container
    } else {
        checkJsonText(path, reinterpret_cast<const char*>(bytes.data()), bytes.size());
    }

    Parsed parsed = parseWithTinyGltf(path, bytes, binary);
    bytes = {};  // tinygltf has copied what it needs
    const tinygltf::Model& model = parsed.model;
    checkAssetVersion(path, model);
    checkRequiredExtensions(path, model);
    checkBufferDataUris(path, model);
    checkBufferViews(path, model);

    Scene scene;
    scene.name = fs::path(path).stem().string();
    Skipped skipped;
    SceneBuilder builder(path, model, scene, skipped);
    std::vector<std::optional<MeshPlan>> plans(model.meshes.size());
    for (const MeshInstance& instance : flattenNodes(path, model)) {
        std::optional<MeshPlan>& plan = plans[instance.mesh];
        if (!plan) plan = planMesh(path, model, instance.mesh, skipped);
        builder.addInstance(instance, *plan);
    }
    if (scene.indices.empty()) fail(path, "the scene has no triangles to draw (empty scene)");
    builder.finish();
    computeBounds(scene);

    for (const std::string& line : unmodelledFeatures(model, skipped)) warnings.push_back(path + ": " + line);
    if (!parsed.tinygltfWarnings.empty()) warnings.push_back(path + ": glTF parser: " + parsed.tinygltfWarnings);
    return scene;
}

}  // namespace

Scene loadGltf(const std::string& path, std::vector<std::string>& warnings) {
    try {
        return loadChecked(path, warnings);
    } catch (const std::bad_alloc&) {
        // The limits keep input from asking for more than a few GiB, which a machine may still lack.
        fail(path, "out of memory while loading");
    }
}

}  // namespace ml
