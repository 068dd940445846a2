// oiio_shim.cpp — the image module (sylva_image.so, io/image_module.h),
// image_io.h's reading and writing on OpenImageIO, loaded by the core on first use
// (io/image_io.c). Every operation catches whatever OpenImageIO or the standard library throws
// and turns it into an err_buf sentence; memory handed back to C is malloc'd so image_free can
// release it. Alpha is read and written unassociated, so pixel values pass through unchanged.
// The core's functions it needs come through the host's table; of the core it links only
// util/err.c, which holds no state.
extern "C" {
#include "io/atomic_file.h"
#include "io/photo.h"
#include "util/err.h"
}
#include "io/image_io.h"
#include "io/image_module.h"

#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cmath>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace {

// The core's functions, from the entry point; static data of the core.
const image_host *host = nullptr;

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

// The whole image as float samples, channels interleaved, into dst. A scanline file is read a
// row at a time: OpenImageIO 2.4's read_image stages a scanline file through a 64 MiB buffer
// however small the image, memory the budget does not see. A tiled file goes through read_image.
bool read_float_pixels(OIIO::ImageInput *in, float *dst)
{
    const OIIO::ImageSpec &spec = in->spec();
    if (spec.tile_width > 0)
        return in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, dst);
    const size_t row = static_cast<size_t>(spec.width) * static_cast<size_t>(spec.nchannels);
    for (int y = 0; y < spec.height; y++)
        if (!in->read_scanline(spec.y + y, spec.z, OIIO::TypeDesc::FLOAT, dst + static_cast<size_t>(y) * row))
            return false;
    return true;
}

// Reads the pixels into dst and says what was wrong with them: "" when they all read cleanly,
// else the first line of OpenImageIO's complaint (a TIFF gives one per missing strip). A read
// that fails is damage, and so is one that succeeded with a note: libjpeg lets a reader go on
// past the end of a file cut short, fills the rest of the image with grey and only records it.
std::string pixels_damage(OIIO::ImageInput *in, float *dst)
{
    (void)in->geterror(); // anything noted while opening is not about the pixels
    const bool read = read_float_pixels(in, dst);
    std::string why = in->geterror();
    if (read && why.empty()) return why;
    if (why.empty()) why = "the pixels could not be read";
    const size_t eol = why.find('\n');
    return eol == std::string::npos ? why : why.substr(0, eol);
}

// The memory a JPEG's decoding would take, from the frame its markers state, checked against
// the budget before OpenImageIO opens it (libjpeg allocates for the whole frame on opening):
// `need_per_sample` bytes for each sample and `extra_per_pixel` for each pixel, as the caller
// will hold them. `what` names the read in the refusal.
int jpeg_budget(const char *path, const char *what, uint64_t need_per_sample, uint64_t extra_per_pixel,
                err_buf *err)
{
    uint32_t w = 0, h = 0, c = 0;
    if (!host->jpeg_frame(path, &w, &h, &c)) return 0;
    const uint64_t need = static_cast<uint64_t>(w) * h * (c * need_per_sample + extra_per_pixel);
    const std::string label = std::string(what) + " '" + path + "' (" + std::to_string(w) + "x" +
                              std::to_string(h) + ", as its JPEG frame states)";
    return host->memory_check(need, label.c_str(), err) ? err_default(err, ERR_LIMIT) : 0;
}

// Reads the file `path`, or the `size` bytes at `bytes` behind `proxy` when it is not NULL
// (OpenImageIO then takes the format from the extension of `open_name`); `path` names the image
// in messages.
int read_into(const char *path, const char *open_name, OIIO::Filesystem::IOProxy *proxy, const void *bytes,
              size_t size, image_f32 *img, err_buf *err)
{
    if (!proxy) {
        // A FIFO or device would block OpenImageIO's format detection or feed it without end.
        const std::string label = std::string(path) + ": cannot read the image";
        if (host->file_check_regular(path, label.c_str(), err)) return -1;
        if (access(path, R_OK) != 0) // OpenImageIO would only say it could not open the file
            return err_set(err, "%s: cannot read the image: %s", path, std::strerror(errno));
        if (jpeg_budget(path, "reading the image", sizeof(float), IMAGE_READ_COPY_BYTES_PER_PIXEL, err))
            return -1;
    }
    if (host->png_read_check(path, bytes, size, 0, err)) return -1; // before libpng prints or allocates
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
        return err_fail(err, ERR_LIMIT, "%s: cannot read the image: %dx%d pixels with %d channels "
                        "is too large", path, spec.width, spec.height, spec.nchannels);
    // The size comes from the file's header alone (any file can claim 60000 x 60000): checked
    // against the memory budget before anything is allocated, as photographs and DTMs are.
    const uint64_t n_px = static_cast<uint64_t>(spec.width) * static_cast<uint64_t>(spec.height);
    const uint64_t need = n_px * (static_cast<uint64_t>(spec.nchannels) * sizeof(float) +
                                  IMAGE_READ_COPY_BYTES_PER_PIXEL);
    const std::string what = std::string("reading the image '") + path + "' (" +
                             std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                             ", " + std::to_string(spec.nchannels) + " channels)";
    if (host->memory_check(need, what.c_str(), err)) return err_default(err, ERR_LIMIT);
    if (host->png_read_check(path, bytes, size, 1, err)) return -1;

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
    const std::string damage = pixels_damage(in.get(), img->pixels);
    if (!damage.empty())
        return err_set(err, "%s: cannot read the image: it is damaged or cut short (OpenImageIO "
                       "says: %s)", path, damage.c_str());
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
    spec.attribute("Software", SYLVA_SOFTWARE_TAG); /* tells a render from a photograph (io/photo.h) */
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
            status = read_into(path, open_name.c_str(), &proxy, bytes, size, &img, err);
        } else {
            status = read_into(path, path, nullptr, nullptr, 0, &img, err);
        }
    } catch (const std::exception &e) {
        status = err_set(err, "%s: cannot read the image: %s", path, e.what());
    } catch (...) {
        status = err_set(err, "%s: cannot read the image: unknown failure in OpenImageIO", path);
    }
    if (status) {
        host->image_free(&img);
        return -1;
    }
    *out = img;
    return 0;
}


// --- photographs: pixels as stored and the EXIF record (io/photo.h) --------------------------

// The attribute `name` (case-insensitive: OpenImageIO spells a DateTimeOriginal found in IFD0
// "exif:DateTimeOriginal"), or NULL.
const OIIO::ParamValue *photo_attr(const OIIO::ImageSpec &spec, const char *name)
{
    return spec.find_attribute(name, OIIO::TypeDesc::UNKNOWN, false);
}

// The string attribute `name` copied into dst (size n); 1 when it is present and not empty.
int photo_attr_text(const OIIO::ImageSpec &spec, const char *name, char *dst, size_t n)
{
    const OIIO::ParamValue *p = photo_attr(spec, name);
    if (!p || p->type().basetype != OIIO::TypeDesc::STRING) return 0;
    std::string v = p->get_string();
    while (!v.empty() && (v.back() == ' ' || v.back() == '\0')) v.pop_back();
    if (v.empty()) return 0;
    std::snprintf(dst, n, "%s", v.c_str());
    return 1;
}

// The numeric attribute `name` holding at least `count` values, into v; 1 when present and
// every value is finite.
int photo_attr_numbers(const OIIO::ImageSpec &spec, const char *name, double *v, int count)
{
    const OIIO::ParamValue *p = photo_attr(spec, name);
    if (!p || p->type().basetype == OIIO::TypeDesc::STRING) return 0;
    const int have = p->nvalues() * static_cast<int>(p->type().numelements()) *
                     static_cast<int>(p->type().aggregate);
    if (have < count) return 0;
    for (int i = 0; i < count; i++) {
        v[i] = p->get_float_indexed(i, NAN);
        if (!std::isfinite(v[i])) return 0;
    }
    return 1;
}

// Degrees, minutes and seconds signed by their reference letter (`negative` is "S" or "W").
int photo_gps_angle(const OIIO::ImageSpec &spec, const char *name, const char *ref_name,
                    char negative, double limit, double *out)
{
    double dms[3];
    if (!photo_attr_numbers(spec, name, dms, 3)) return 0;
    double deg = dms[0] + dms[1] / 60.0 + dms[2] / 3600.0;
    char ref[8] = "";
    photo_attr_text(spec, ref_name, ref, sizeof ref);
    if (ref[0] == negative) deg = -deg;
    if (!(std::fabs(deg) <= limit)) return 0;
    *out = deg;
    return 1;
}

void photo_read_exif(const OIIO::ImageSpec &spec, photo_exif *x)
{
    *x = photo_exif{};
    x->has_make = photo_attr_text(spec, "Make", x->make, sizeof x->make);
    x->has_model = photo_attr_text(spec, "Model", x->model, sizeof x->model);
    x->has_lens_model = photo_attr_text(spec, "Exif:LensModel", x->lens_model, sizeof x->lens_model);
    double v[3];
    if (photo_attr_numbers(spec, "Exif:FocalLength", v, 1) && v[0] > 0)
        x->has_focal_length = 1, x->focal_length_mm = v[0];
    if (photo_attr_numbers(spec, "Exif:FocalLengthIn35mmFilm", v, 1) && v[0] > 0)
        x->has_focal_length_35mm = 1, x->focal_length_35mm = v[0];
    double fx, fy, unit = 2; // EXIF's default unit is the inch
    if (photo_attr_numbers(spec, "Exif:FocalPlaneXResolution", &fx, 1) &&
        photo_attr_numbers(spec, "Exif:FocalPlaneYResolution", &fy, 1) && fx > 0 && fy > 0) {
        photo_attr_numbers(spec, "Exif:FocalPlaneResolutionUnit", &unit, 1);
        if (unit >= 2 && unit <= 5 && unit == std::floor(unit)) {
            x->has_focal_plane = 1;
            x->focal_plane_x_res = fx, x->focal_plane_y_res = fy;
            x->focal_plane_unit = static_cast<int>(unit);
        }
    }
    x->has_gps_position =
        photo_gps_angle(spec, "GPS:Latitude", "GPS:LatitudeRef", 'S', 90.0, &x->latitude_deg) &&
        photo_gps_angle(spec, "GPS:Longitude", "GPS:LongitudeRef", 'W', 180.0, &x->longitude_deg);
    if (photo_attr_numbers(spec, "GPS:Altitude", v, 1)) {
        double ref = 0;
        photo_attr_numbers(spec, "GPS:AltitudeRef", &ref, 1);
        x->has_gps_altitude = 1, x->altitude_m = ref == 1 ? -v[0] : v[0];
    }
    if (photo_attr_numbers(spec, "GPS:ImgDirection", v, 1) && v[0] >= 0 && v[0] <= 360) {
        char ref[8] = "";
        photo_attr_text(spec, "GPS:ImgDirectionRef", ref, sizeof ref);
        x->has_gps_direction = 1, x->direction_deg = v[0], x->direction_true = ref[0] != 'M';
    }
    char text[64];
    if (photo_attr_text(spec, "Exif:DateTimeOriginal", text, sizeof text) &&
        std::sscanf(text, "%4d:%2d:%2d %2d:%2d:%2d", &x->year, &x->month, &x->day, &x->hour,
                    &x->minute, &x->second) == 6 &&
        x->month >= 1 && x->month <= 12 && x->day >= 1 && x->day <= 31 && x->hour >= 0 &&
        x->hour <= 23 && x->minute >= 0 && x->minute <= 59 && x->second >= 0 && x->second <= 60)
        x->has_date_time = 1;
    char sign;
    int oh, om;
    if (photo_attr_text(spec, "Exif:OffsetTimeOriginal", text, sizeof text) &&
        std::sscanf(text, "%c%2d:%2d", &sign, &oh, &om) == 3 && (sign == '+' || sign == '-') &&
        oh >= 0 && oh <= 14 && om >= 0 && om <= 59)
        x->has_utc_offset = 1, x->utc_offset_min = (sign == '-' ? -1 : 1) * (oh * 60 + om);
    x->orientation = spec.get_int_attribute("Orientation", 1);
    photo_attr_text(spec, "ICCProfile:profile_description", x->icc_profile, sizeof x->icc_profile);
}

// The OpenImageIO reader for a photograph, named from the file's first bytes: a JPEG, PNG or
// TIFF (classic or BigTIFF, either byte order); NULL for anything else. Only that reader sees
// the file: OpenImageIO on its own tries each of its dozens of readers in turn on a file its
// extension's reader refuses.
const char *photo_format(const unsigned char *b, size_t n)
{
    if (n >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff) return "jpeg";
    if (n >= 4 && b[0] == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G') return "png";
    if (n >= 4 && ((b[0] == 'I' && b[1] == 'I' && (b[2] == 42 || b[2] == 43) && b[3] == 0) ||
                   (b[0] == 'M' && b[1] == 'M' && b[2] == 0 && (b[3] == 42 || b[3] == 43))))
        return "tiff";
    return nullptr;
}

int photo_read_into(const char *path, image_f32 *img, photo *meta, err_buf *err)
{
    const std::string label = std::string(path) + ": cannot read the photograph";
    if (host->file_check_regular(path, label.c_str(), err)) return -1;
    if (access(path, R_OK) != 0)
        return err_fail(err, ERR_INPUT, "%s: cannot read the photograph: %s", path,
                        std::strerror(errno));
    unsigned char head[4] = {0};
    FILE *f = std::fopen(path, "rb");
    const size_t n_head = f ? std::fread(head, 1, sizeof head, f) : 0;
    if (f) std::fclose(f);
    const char *format = photo_format(head, n_head);
    if (!format)
        return err_fail(err, ERR_INPUT, "%s: cannot read the photograph (a JPEG, PNG or TIFF "
                        "file is expected): its first bytes are none of theirs", path);
    if (host->png_read_check(path, nullptr, 0, 0, err)) return -1; // before libpng prints or allocates
    if (jpeg_budget(path, "reading the photograph", sizeof(float), 3 * sizeof(float), err)) return -1;
    auto in = OIIO::ImageInput::create(format);
    OIIO::ImageSpec opened;
    if (!in || !in->open(path, opened)) {
        std::string why = in ? in->geterror() : OIIO::geterror();
        return err_fail(err, ERR_INPUT, "%s: cannot read the photograph (a JPEG, PNG or TIFF "
                        "file is expected): OpenImageIO says: %s", path,
                        why.empty() ? "it cannot open the file" : why.c_str());
    }
    const OIIO::ImageSpec &spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
        return err_fail(err, ERR_INPUT, "%s: cannot read the photograph: it is %dx%dx%d with %d "
                        "channels; a flat image with at least one pixel is needed",
                        path, spec.width, spec.height, spec.depth, spec.nchannels);
    photo_read_exif(spec, &meta->exif);
    if (meta->exif.orientation < 1 || meta->exif.orientation > 8)
        return err_fail(err, ERR_INPUT, "%s: the EXIF Orientation is %d; the photograph cannot be "
                        "turned upright (1 to 8 are defined)", path, meta->exif.orientation);
    const uint64_t n_px = static_cast<uint64_t>(spec.width) * static_cast<uint64_t>(spec.height);
    const uint64_t need = n_px * (static_cast<uint64_t>(spec.nchannels) + 3) * sizeof(float);
    const std::string what = std::string("reading the photograph '") + path + "' (" +
                             std::to_string(spec.width) + "x" + std::to_string(spec.height) + ")";
    if (host->memory_check(need, what.c_str(), err)) return err_default(err, ERR_LIMIT);
    if (host->png_read_check(path, nullptr, 0, 1, err)) return -1;
    if (n_px * static_cast<uint64_t>(spec.nchannels) > SIZE_MAX / sizeof(float))
        return err_fail(err, ERR_LIMIT, "%s: the photograph is too large to address", path);

    meta->stored_width = static_cast<uint32_t>(spec.width);
    meta->stored_height = static_cast<uint32_t>(spec.height);
    meta->bits = static_cast<int>(spec.format.size() * 8);
    meta->is_float = spec.format.is_floating_point();
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    std::snprintf(meta->colour_space, sizeof meta->colour_space, "%s", cs.c_str());
    const std::string software = spec.get_string_attribute("Software");
    meta->sylva_render = software.compare(0, std::strlen(SYLVA_SOFTWARE_TAG), SYLVA_SOFTWARE_TAG) == 0 ||
                         photo_attr(spec, "exposureStops") != nullptr;

    const size_t count = static_cast<size_t>(n_px) * static_cast<size_t>(spec.nchannels);
    img->width = meta->stored_width, img->height = meta->stored_height;
    img->pixels = static_cast<float *>(std::malloc(count * sizeof(float)));
    if (!img->pixels)
        return err_nomem(err, "%s: out of memory for %zu float samples", path, count);
    img->channels = static_cast<uint32_t>(spec.nchannels);
    const std::string damage = pixels_damage(in.get(), img->pixels);
    if (!damage.empty())
        return err_fail(err, ERR_INPUT, "%s: cannot read the photograph: it is damaged or cut "
                        "short (OpenImageIO says: %s)", path, damage.c_str());
    in->close();
    return 0;
}

int module_read(const char *path, image_f32 *out, err_buf *err)
{
    return read_guarded(path, nullptr, 0, nullptr, out, err);
}

int module_read_memory(const void *bytes, size_t size, const char *format, const char *name, image_f32 *out,
                       err_buf *err)
{
    return read_guarded(name, bytes, size, format, out, err);
}

int module_write_u8_into(atomic_file *af, uint32_t width, uint32_t height, uint32_t channels,
                         const uint8_t *pixels, err_buf *err)
{
    const char *path = af->path;
    try {
        return write_u8(path, af, width, height, channels, pixels, err);
    } catch (const std::exception &e) {
        return err_set(err, "%s: cannot write the image: %s", path, e.what());
    } catch (...) {
        return err_set(err, "%s: cannot write the image: unknown failure in OpenImageIO", path);
    }
}

int module_read_photo(const char *path, image_f32 *stored, photo *meta, err_buf *err)
{
    image_f32 img{};
    int status;
    try {
        status = photo_read_into(path, &img, meta, err);
    } catch (const std::exception &e) {
        status = err_fail(err, ERR_INPUT, "%s: cannot read the photograph: OpenImageIO says: %s",
                          path, e.what());
    } catch (...) {
        status = err_fail(err, ERR_INPUT, "%s: cannot read the photograph: unknown failure in "
                          "OpenImageIO", path);
    }
    if (status) {
        host->image_free(&img);
        return -1;
    }
    *stored = img;
    return 0;
}

const image_module operations = {sizeof(image_module), IMAGE_MODULE_VERSION, module_read, module_read_memory,
                                 module_write_u8_into, module_read_photo};

} // namespace

// The module's one exported symbol (io/image_module.h): NULL for a host whose table is older
// than the one this module was built with.
extern "C" __attribute__((visibility("default"))) const image_module *sylva_image_module(const image_host *h)
{
    if (!h || h->size < sizeof(image_host)) return nullptr;
    host = h;
    return &operations;
}
