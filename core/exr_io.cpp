#include "core/exr_io.h"

#include "core/atomic_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <exception>

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
        throw ImageError(path + ": cannot write: " + e.what());
    }
}

Image readExr(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
        if (w <= 0 || h <= 0 || int64_t(w) * h > (int64_t(1) << 30))
            throw ImageError(path + ": unreasonable data window");
        Image image(w, h);
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
            auto& data = image.channels[name];
            data.assign(size_t(w) * h, 0.0f);
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
