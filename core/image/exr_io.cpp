#include "core/image/exr_io.h"

#include "core/atomic_file.h"
#include "core/message_text.h"
#include "core/regular_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/openexr.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <sys/stat.h>

namespace lucerna {

void writeExr(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0)
        throw ImageError(path + ": cannot write an empty image");
    try {
        writeAtomically(path, [&](const std::string& temp) {
            Imf::Header header(image.width, image.height);
            header.compression() = Imf::ZIP_COMPRESSION;
            for (const auto& [name, value] : image.attributes)
                header.insert(name, Imf::StringAttribute(value));
            Imf::FrameBuffer fb;
            const size_t xStride = sizeof(Rgb), yStride = xStride * size_t(image.width);
            char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
            const char* names[3] = {"R", "G", "B"};
            for (int c = 0; c < 3; ++c) {
                header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
                fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
            }
            // OpenEXR keeps channels sorted by name, so R, G, B come before lower-case layer names
            // such as albedo.R; an extra channel may not shadow them.
            for (const auto& [name, data] : image.channels) {
                if (name.empty() || name == "R" || name == "G" || name == "B")
                    throw ImageError(path + ": extra channel name '" + name + "' is empty or clashes with R, G, B");
                if (data.size() != image.pixelCount())
                    throw ImageError(path + ": channel " + name + " has the wrong size");
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
                fb.insert(name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(data.data())),
                                           sizeof(float), sizeof(float) * size_t(image.width)));
            }
            Imf::OutputFile file(temp.c_str(), header);
            file.setFrameBuffer(fb);
            file.writePixels(image.height);
        });
    } catch (const ImageError&) {
        throw;
    } catch (const std::exception& e) {
        std::string msg = e.what();
        if (const auto nl = msg.find('\n'); nl != std::string::npos) msg.resize(nl);
        throw ImageError(path + ": cannot write: " + msg);
    }
}

namespace {

// Whether an attribute's value, as InputFile reads it (by its type's content), takes exactly
// the declared size. Types read by their size (strings, vectors, unknown types) always do.
bool contentMatchesSize(const std::string& type, const std::string& value) {
    static const std::pair<const char*, size_t> kFixed[] = {
        {"box2i", 16}, {"box2f", 16}, {"compression", 1}, {"lineOrder", 1}, {"envmap", 1}, {"deepImageState", 1},
        {"float", 4}, {"double", 8}, {"int", 4}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12},
        {"v3d", 24}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"chromaticities", 32},
        {"keycode", 28}, {"timecode", 8}, {"rational", 8}, {"tiledesc", 9}};
    for (const auto& [name, size] : kFixed)
        if (type == name) return value.size() == size;
    if (type == "chlist") {  // entries of a name, its NUL and 16 bytes, up to an empty name
        size_t at = 0;
        while (at < value.size() && value[at] != '\0') {
            const size_t nul = value.find('\0', at);
            if (nul == std::string::npos) return false;
            at = nul + 1 + 16;
        }
        return at + 1 == value.size();
    }
    if (type == "preview") {  // width, height, then 4 bytes a pixel
        if (value.size() < 8) return false;
        uint32_t w = 0, h = 0;
        std::memcpy(&w, value.data(), 4);
        std::memcpy(&h, value.data() + 4, 4);
        return 8 + 4 * uint64_t(w) * uint64_t(h) == value.size();
    }
    return true;
}

// OpenEXR's InputFile allocates each header attribute's declared size before reading it (a
// string or an attribute of unknown type claiming 1.7 GB in a file of 700 bytes): every declared
// size must fit in what follows it in the file. Walks the header(s) (several in a multi-part
// file); returns the problem, or nothing.
std::string attributeBeyondFile(const std::string& path, uint64_t fileSize) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return {};
    unsigned char head[8];
    std::string problem;
    if (std::fread(head, 1, 8, f) == 8) {
        const bool multipart = head[5] & 0x10;  // version flags 0x1000
        const auto text = [&](std::string& out) {  // a NUL-terminated name, at most 255 characters
            out.clear();
            for (int c; (c = std::fgetc(f)) != EOF;) {
                if (c == 0) return true;
                if (out.size() == 255) return false;
                out += char(c);
            }
            return false;
        };
        for (bool more = true; more && problem.empty();) {
            std::string name, type;
            while (problem.empty()) {
                if (!text(name)) return std::fclose(f), std::string();  // cut short: InputFile says so
                if (name.empty()) break;                                 // the end of this header
                unsigned char size[4];
                if (!text(type) || std::fread(size, 1, 4, f) != 4) return std::fclose(f), std::string();
                const int64_t bytes = int32_t(uint32_t(size[0]) | uint32_t(size[1]) << 8 | uint32_t(size[2]) << 16 |
                                              uint32_t(size[3]) << 24);
                const int64_t at = std::ftell(f);
                if (bytes < 0 || at < 0 || uint64_t(at) + uint64_t(bytes) > fileSize) {
                    problem = "the header's attribute \"" + printableWord(name) + "\" claims " + std::to_string(bytes) +
                              " bytes, more than the file holds";
                    break;
                }
                // InputFile reads known types by their content, not by the declared size: the
                // two must agree, or its reading and this walk part ways.
                std::string value(size_t(bytes), '\0');
                if (std::fread(value.data(), 1, value.size(), f) != value.size()) return std::fclose(f), std::string();
                if (!contentMatchesSize(type, value))
                    problem = "the header's attribute \"" + printableWord(name) + "\" (" + printableWord(type) +
                              ") is malformed: its content and its declared size of " + std::to_string(bytes) + " bytes differ";
            }
            // A multi-part file ends its list of headers with an empty one.
            more = multipart && problem.empty() && [&] {
                const int c = std::fgetc(f);
                if (c == 0 || c == EOF) return false;
                std::ungetc(c, f);
                return true;
            }();
        }
    }
    std::fclose(f);
    return problem;
}

// How many times its packed size a chunk may unpack to, by codec, with room to spare: none 1;
// RLE stores a run of up to 128 bytes in 2; B44 a 4 x 4 block of halves in at least 3 bytes;
// deflate (ZIP, ZIPS, and PXR24 after it drops a byte of each float) stops near 1032 to 1;
// PIZ and DWA, whose stages multiply, get 65536.
uint64_t maxCompressionRatio(exr_compression_t c) {
    switch (c) {
    case EXR_COMPRESSION_NONE: return 1;
    case EXR_COMPRESSION_RLE: return 128;
    case EXR_COMPRESSION_B44:
    case EXR_COMPRESSION_B44A: return 64;
    case EXR_COMPRESSION_ZIPS:
    case EXR_COMPRESSION_ZIP: return 2048;
    case EXR_COMPRESSION_PXR24: return 4096;
    default: return 65536;
    }
}

// The header alone decides how much readExr allocates, and a 200 KB file can claim 16384 x 16384
// pixels; so before anything is allocated (OpenEXR's InputFile allocates the offset table the
// header implies), the file must hold that offset table, and every chunk of pixel data a
// scan-line header promises must lie within the file: OpenEXR's core library reads each chunk's
// offset and size (a few bytes each); together they must fit in the file (chunks that overlap
// would let one stretch of bytes claim to be every chunk). A chunk may not unpack to more than
// its codec can make of its packed size either (maxCompressionRatio), which bounds the image by
// the file's size.
// Tiled and deep files are left to InputFile::isComplete. Returns the problem, or nothing.
std::string missingPixelData(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return {};
    const uint64_t fileSize = uint64_t(st.st_size);
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = [](exr_const_context_t, exr_result_t, const char*) {};  // reported below instead
    exr_context_t ctx = nullptr;
    std::string problem = attributeBeyondFile(path, fileSize);
    if (!problem.empty()) return problem;
    // The core library checks each header attribute's size against the file; InputFile does not
    // (a string attribute claiming 2 GB makes it allocate 2 GB), so a header the core library
    // refuses is not handed on.
    if (const exr_result_t started = exr_start_read(&ctx, path.c_str(), &init); started != EXR_ERR_SUCCESS) {
        problem = std::string("not a valid EXR file (") + exr_get_default_error_message(started) + ")";
    } else {
        int parts = 0;
        exr_get_count(ctx, &parts);
        uint64_t tables = 0;
        for (int p = 0; p < parts; ++p) {
            int32_t chunks = 0;
            if (exr_get_chunk_count(ctx, p, &chunks) == EXR_ERR_SUCCESS && chunks > 0) tables += 8 * uint64_t(chunks);
        }
        if (tables > fileSize)
            problem = "the file (" + std::to_string(fileSize) + " bytes) is shorter than the offset table its header implies (" +
                      std::to_string(tables) + " bytes)";
        // Every storage (tiled and deep parts too): what readExr would allocate, a float per
        // channel and pixel, at most 131072 times the file (65536 for the codecs, 2 for halves).
        for (int p = 0; p < parts && problem.empty(); ++p) {
            exr_attr_box2i_t dw{};
            const exr_attr_chlist_t* channels = nullptr;
            if (exr_get_data_window(ctx, p, &dw) != EXR_ERR_SUCCESS || exr_get_channels(ctx, p, &channels) != EXR_ERR_SUCCESS ||
                !channels)
                continue;
            const double pixels = (double(dw.max.x) - dw.min.x + 1) * (double(dw.max.y) - dw.min.y + 1);
            const double bytes = pixels * 4.0 * std::max(3, channels->num_channels);
            if (bytes > 131072.0 * double(fileSize))
                problem = "the file's " + std::to_string(fileSize) + " bytes cannot hold the " +
                          std::to_string(dw.max.x - int64_t(dw.min.x) + 1) + " x " +
                          std::to_string(dw.max.y - int64_t(dw.min.y) + 1) + " pixels its header claims";
        }
        for (int p = 0; p < parts && problem.empty(); ++p) {
            exr_storage_t storage{};
            exr_attr_box2i_t dw{};
            exr_compression_t compression{};
            int32_t lines = 0;
            if (exr_get_storage(ctx, p, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE ||
                exr_get_data_window(ctx, p, &dw) != EXR_ERR_SUCCESS ||
                exr_get_compression(ctx, p, &compression) != EXR_ERR_SUCCESS ||
                exr_get_scanlines_per_chunk(ctx, p, &lines) != EXR_ERR_SUCCESS || lines <= 0)
                continue;
            const uint64_t ratio = maxCompressionRatio(compression);
            uint64_t packedTotal = 0;  // chunks do not overlap: together they fit in the file
            for (int64_t y = dw.min.y; y <= dw.max.y; y += lines) {
                exr_chunk_info_t chunk{};
                if (exr_read_scanline_chunk_info(ctx, p, int(y), &chunk) != EXR_ERR_SUCCESS ||
                    chunk.data_offset > fileSize || chunk.packed_size > fileSize - chunk.data_offset) {
                    problem = "the file lacks the pixel data its header promises (scan line " + std::to_string(y) + " of " +
                              std::to_string(dw.min.y) + " to " + std::to_string(dw.max.y) + ")";
                    break;
                }
                packedTotal += chunk.packed_size;
                if (packedTotal > fileSize) {
                    problem = "the chunks of pixel data up to scan line " + std::to_string(y) +
                              " add up to more than the file holds (they overlap)";
                    break;
                }
                if (chunk.unpacked_size / ratio > chunk.packed_size) {
                    problem = "the pixel data of scan line " + std::to_string(y) + " (" + std::to_string(chunk.packed_size) +
                              " bytes) cannot hold the " + std::to_string(chunk.unpacked_size) + " bytes its header claims";
                    break;
                }
            }
        }
    }
    exr_finish(&ctx);
    return problem;
}

}  // namespace

Image readExr(const std::string& path) {
    if (const std::string kind = nonRegularFileKind(path); !kind.empty())
        throw ImageError(path + ": cannot read: not a regular file (" + kind + ")");
    if (const std::string problem = missingPixelData(path); !problem.empty()) throw ImageError(path + ": " + problem);
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
        if (w <= 0 || h <= 0 || int64_t(w) * h > (int64_t(1) << 30))
            throw ImageError(path + ": unreasonable data window");
        if (!file.isComplete()) throw ImageError(path + ": the file lacks the pixel data its header promises");
        Image image;
        try {
            image = Image(w, h);
            for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
                if (std::string name = it.name(); name != "R" && name != "G" && name != "B")
                    image.channels[name].assign(size_t(w) * h, 0.0f);
        } catch (const std::bad_alloc&) {
            throw ImageError(path + ": a " + std::to_string(w) + " x " + std::to_string(h) +
                             " image with its channels is more than the memory available");
        }
        const Imf::ChannelList& channels = file.header().channels();
        for (const char* c : {"R", "G", "B"})
            if (!channels.findChannel(c))
                throw ImageError(path + ": no " + c + " channel");
        // OpenEXR addresses the frame buffer by absolute data-window coordinates.
        const ptrdiff_t origin = -(ptrdiff_t(dw.min.x) + ptrdiff_t(dw.min.y) * w);
        Imf::FrameBuffer fb;
        char* base = reinterpret_cast<char*>(image.pixels.data()) + origin * ptrdiff_t(sizeof(Rgb));
        const size_t xStride = sizeof(Rgb), yStride = xStride * size_t(w);
        fb.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
        fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
        for (auto it = channels.begin(); it != channels.end(); ++it) {
            const std::string name = it.name();
            if (name == "R" || name == "G" || name == "B") continue;
            auto& data = image.channels[name];  // allocated above
            char* cbase = reinterpret_cast<char*>(data.data()) + origin * ptrdiff_t(sizeof(float));
            fb.insert(name, Imf::Slice(Imf::FLOAT, cbase, sizeof(float), sizeof(float) * size_t(w)));
        }
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        for (auto it = file.header().begin(); it != file.header().end(); ++it)
            if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
                image.attributes[it.name()] = s->value();
        return image;
    } catch (const ImageError&) {
        throw;
    } catch (const std::exception& e) {
        std::string msg = e.what();
        if (const auto nl = msg.find('\n'); nl != std::string::npos) msg.resize(nl);
        throw ImageError(path + ": cannot read: " + msg);
    }
}

}  // namespace lucerna
