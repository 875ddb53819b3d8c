// glTF 2.0 containers through tinygltf 2.7.
//
// tinygltf parses the JSON and fetches buffers, but checks little of what the model then refers
// to: buffer views, accessors, indices and node links may point anywhere. Everything the loader
// reads from a tinygltf::Model is therefore bounds-checked first (buffer views here, the rest
// where it is read), so that bad input ends in one SceneError line rather than a crash, a hang or
// a runaway allocation.
#include "scenes/gltf_container.h"

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "scenes/gltf_common.h"
#include "scenes/gltf_compressed_json.h"
#include "scenes/gltf_meshopt.h"

namespace ml::gltf {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kGlbChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kGlbChunkBin = 0x004E4942;   // "BIN\0"

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

// The same container with another JSON chunk (padded with spaces, as GLB asks) and the same BIN chunk.
std::vector<unsigned char> withJsonChunk(const std::vector<unsigned char>& bytes, const GlbLayout& glb, std::string json) {
    while (json.size() % 4 != 0) json += ' ';
    const std::size_t binStart = glb.jsonOffset + glb.jsonSize;
    std::vector<unsigned char> out;
    const auto putU32 = [&](std::size_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
    };
    putU32(kGlbMagic);
    putU32(2);
    putU32(20 + json.size() + (glb.length - binStart));
    putU32(json.size());
    putU32(kGlbChunkJson);
    out.insert(out.end(), json.begin(), json.end());
    out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(binStart), bytes.begin() + static_cast<std::ptrdiff_t>(glb.length));
    return out;
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

ParsedGltf parseWithTinyGltf(const std::string& path, const std::vector<unsigned char>& bytes, bool binary) {
    ParsedGltf parsed;
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

}  // namespace

ParsedGltf readGltfContainer(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".gltf" && ext != ".glb") fail(path, "not a glTF file (expected a .gltf or .glb extension)");
    const bool binary = ext == ".glb";

    std::vector<unsigned char> bytes;
    std::string why;
    if (!readRegularFile(path, bytes, why)) fail(path, "cannot open glTF file: " + why);
    SetAside aside;
    if (binary) {
        const GlbLayout glb = checkGlbContainer(path, bytes);
        const char* json = reinterpret_cast<const char*>(bytes.data() + glb.jsonOffset);
        checkJsonText(path, json, glb.jsonSize);
        bytes.resize(glb.length);  // bytes past the stated length are not part of the container
        if (auto rewritten = setAsideForTinyGltf({json, glb.jsonSize}, binary, aside))
            bytes = withJsonChunk(bytes, glb, std::move(*rewritten));
    } else {
        const char* json = reinterpret_cast<const char*>(bytes.data());
        checkJsonText(path, json, bytes.size());
        if (auto rewritten = setAsideForTinyGltf({json, bytes.size()}, binary, aside))
            bytes.assign(rewritten->begin(), rewritten->end());
    }

    ParsedGltf parsed = parseWithTinyGltf(path, bytes, binary);
    bytes = {};  // tinygltf has copied what it needs
    tinygltf::Model& model = parsed.model;
    putBack(aside, model);
    checkAssetVersion(path, model);
    checkBufferDataUris(path, model);
    parsed.warnings = decodeMeshoptViews(path, model);
    checkBufferViews(path, model);
    return parsed;
}

}  // namespace ml::gltf
