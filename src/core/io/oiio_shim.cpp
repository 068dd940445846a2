// oiio_shim.cpp — the only C++ in sylva: image_io.h implemented on OpenImageIO. Every entry
// point catches whatever OpenImageIO or the standard library throws and turns it into an
// err_buf sentence; memory handed back to C is malloc'd so image_free can release it. Alpha is
// read and written unassociated, so pixel values pass through unchanged.
extern "C" {
#include "io/atomic_file.h"
#include "util/err.h"
#include "util/file_check.h"
}
#include "io/image_io.h"

#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace {

// OpenImageIO scales integer samples into [0, 1] when it converts them to float. That suits
// 8- and 16-bit photographs; 32-bit integer channels hold ids and counts, so they are read
// again in their own type and stored by value.
int read_integer_channel(OIIO::ImageInput *in, int c, image_f32 *img, err_buf *err)
{
    OIIO::TypeDesc type = in->spec().channelformat(c);
    if (type != OIIO::TypeDesc::UINT32 && type != OIIO::TypeDesc::INT32) return 0;
    const size_t n_px = static_cast<size_t>(img->width) * img->height;
    std::vector<uint32_t> raw(n_px);
    if (!in->read_image(0, 0, c, c + 1, type, raw.data())) {
        std::string why = in->geterror();
        return err_set(err, "cannot read the integer channel %d: %s", c, why.c_str());
    }
    for (size_t i = 0; i < n_px; i++) {
        float v = type == OIIO::TypeDesc::UINT32 ? static_cast<float>(raw[i])
                                                 : static_cast<float>(static_cast<int32_t>(raw[i]));
        img->pixels[i * img->channels + static_cast<size_t>(c)] = v;
    }
    return 0;
}

// Reads the file `path`, or the bytes behind `proxy` when it is not NULL (OpenImageIO then
// takes the format from the extension of `open_name`); `path` names the image in messages.
int read_into(const char *path, const char *open_name, OIIO::Filesystem::IOProxy *proxy,
              image_f32 *img, err_buf *err)
{
    if (!proxy) {
        // A FIFO or device would block OpenImageIO's format detection or feed it without end.
        const std::string label = std::string(path) + ": cannot read the image";
        if (file_check_regular(path, label.c_str(), err)) return -1;
        if (access(path, R_OK) != 0) // OpenImageIO would only say it could not open the file
            return err_set(err, "%s: cannot read the image: %s", path, std::strerror(errno));
    }
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    // The readers take the proxy from the configuration when they open; passing it only as
    // the argument leaves them looking for a file of that name.
    if (proxy) config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto in = OIIO::ImageInput::open(open_name, &config, proxy);
    if (!in) {
        // OpenImageIO's reasons quote the file's first bytes ("bad magic number 0x726f"), which
        // may belong to any file a scene names; the sentence says what is wrong without them.
        (void)OIIO::geterror();
        return err_set(err, "%s: cannot read the image: it is not in an image format "
                       "OpenImageIO reads (PNG, JPEG, TIFF, OpenEXR, ...), or it is damaged",
                       path);
    }
    const OIIO::ImageSpec &spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
        return err_set(err, "%s: cannot read the image: it is %dx%dx%d with %d channels; a flat "
                       "image with at least one pixel and one channel is needed",
                       path, spec.width, spec.height, spec.depth, spec.nchannels);
    const size_t count = static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height) *
                         static_cast<size_t>(spec.nchannels);
    if (count > SIZE_MAX / sizeof(float) / 2)
        return err_set(err, "%s: cannot read the image: %dx%d pixels with %d channels is too "
                       "large", path, spec.width, spec.height, spec.nchannels);

    img->width = static_cast<uint32_t>(spec.width);
    img->height = static_cast<uint32_t>(spec.height);
    img->pixels = static_cast<float *>(std::malloc(count * sizeof(float)));
    img->channel_names = static_cast<char **>(std::calloc(spec.nchannels, sizeof(char *)));
    if (!img->pixels || !img->channel_names)
        return err_nomem(err, "%s: out of memory for %zu float samples", path, count);
    img->channels = static_cast<uint32_t>(spec.nchannels);
    for (int c = 0; c < spec.nchannels; c++) {
        const std::string &name = c < static_cast<int>(spec.channelnames.size())
                                      ? spec.channelnames[c]
                                      : std::string();
        img->channel_names[c] = strdup(name.c_str());
        if (!img->channel_names[c])
            return err_nomem(err, "%s: out of memory for the channel names", path);
    }
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img->pixels)) {
        std::string why = in->geterror();
        return err_set(err, "%s: cannot read the pixels: %s", path, why.c_str());
    }
    for (int c = 0; c < spec.nchannels; c++)
        if (read_integer_channel(in.get(), c, img, err)) return err_prefix(err, "%s: ", path);
    in->close();
    return 0;
}

// Writes through an IO proxy on the temporary's stream where the format allows it, so
// OpenImageIO never opens a file by name; other formats open the (already created) temporary.
int write_u8(const char *path, atomic_file *tmp, uint32_t width, uint32_t height,
             uint32_t channels, const uint8_t *pixels, err_buf *err)
{
    // declared before the writer, so the writer (whose destructor may still write) goes first
    OIIO::Filesystem::IOFile proxy(tmp->stream, OIIO::Filesystem::IOProxy::Write);
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        (void)OIIO::geterror();
        return err_set(err, "%s: no image format can be chosen from this file name; use .png, "
                       ".jpg, .tif or .exr", path);
    }
    if (out->supports("ioproxy")) out->set_ioproxy(&proxy);
    OIIO::ImageSpec spec(static_cast<int>(width), static_cast<int>(height),
                         static_cast<int>(channels), OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->open(tmp->tmp, spec)) {
        std::string why = out->geterror();
        return err_set(err, "%s: cannot create the image file: %s", path, why.c_str());
    }
    if (!out->write_image(OIIO::TypeDesc::UINT8, pixels)) {
        std::string why = out->geterror();
        out->close();
        return err_set(err, "%s: cannot write the pixels: %s", path, why.c_str());
    }
    if (!out->close()) {
        std::string why = out->geterror();
        return err_set(err, "%s: cannot finish the image file: %s", path, why.c_str());
    }
    return 0;
}

// read_into with whatever OpenImageIO throws turned into a sentence; *out is set only on
// success. bytes == NULL reads the file `path`; otherwise the image is the `size` bytes in
// memory, encoded as `format`, and `path` only names it.
int read_guarded(const char *path, const void *bytes, size_t size, const char *format,
                 image_f32 *out, err_buf *err)
{
    image_f32 img{};
    int status;
    try {
        if (bytes) {
            OIIO::Filesystem::IOMemReader proxy(bytes, size);
            std::string open_name = std::string("memory.") + format;
            status = read_into(path, open_name.c_str(), &proxy, &img, err);
        } else {
            status = read_into(path, path, nullptr, &img, err);
        }
    } catch (const std::exception &e) {
        status = err_set(err, "%s: cannot read the image: %s", path, e.what());
    } catch (...) {
        status = err_set(err, "%s: cannot read the image: unknown failure in OpenImageIO", path);
    }
    if (status) {
        image_free(&img);
        return -1;
    }
    *out = img;
    return 0;
}

} // namespace

extern "C" int image_read(const char *path, image_f32 *out, err_buf *err)
{
    if (!path || !out) return err_set(err, "image_read needs a path and an output image");
    return read_guarded(path, nullptr, 0, nullptr, out, err);
}

extern "C" int image_read_memory(const void *bytes, size_t size, const char *format,
                                 const char *name, image_f32 *out, err_buf *err)
{
    if (!bytes || !size || !format || !name || !out)
        return err_set(err, "image_read_memory needs bytes, a format and a name");
    return read_guarded(name, bytes, size, format, out, err);
}

extern "C" void image_free(image_f32 *img)
{
    if (!img) return;
    if (img->channel_names)
        for (uint32_t c = 0; c < img->channels; c++) std::free(img->channel_names[c]);
    std::free(img->channel_names);
    std::free(img->pixels);
    *img = image_f32{};
}

extern "C" int image_write_u8_into(atomic_file *af, uint32_t width, uint32_t height,
                                   uint32_t channels, const uint8_t *pixels, err_buf *err)
{
    if (!af || !af->stream || !pixels)
        return err_set(err, "image_write_u8_into needs an open temporary and pixels");
    const char *path = af->path;
    if (width == 0 || height == 0 || width > INT_MAX || height > INT_MAX)
        return err_set(err, "%s: cannot write a %ux%u image; width and height must be between "
                       "1 and %d", path, width, height, INT_MAX);
    if (channels < 1 || channels > 4)
        return err_set(err, "%s: cannot write %u channels; 1 to 4 (grey, grey+alpha, RGB, RGBA) "
                       "are supported", path, channels);
    try {
        return write_u8(path, af, width, height, channels, pixels, err);
    } catch (const std::exception &e) {
        return err_set(err, "%s: cannot write the image: %s", path, e.what());
    } catch (...) {
        return err_set(err, "%s: cannot write the image: unknown failure in OpenImageIO", path);
    }
}

extern "C" int image_write_u8(const char *path, uint32_t width, uint32_t height,
                              uint32_t channels, const uint8_t *pixels, err_buf *err)
{
    if (!path || !pixels) return err_set(err, "image_write_u8 needs a path and pixels");
    atomic_file tmp;
    if (!atomic_file_open_stream(&tmp, path, err)) return -1;
    if (image_write_u8_into(&tmp, width, height, channels, pixels, err)) {
        atomic_file_abort(&tmp);
        return -1;
    }
    return atomic_file_commit(&tmp, err);
}
