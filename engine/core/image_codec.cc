#include "engine/core/image_codec.h"

// clang-format off
#include <png.h>
#include <cstdio>  // jpeglib.h needs FILE and size_t declared first
#include <jpeglib.h>
// clang-format on

#include <csetjmp>
#include <cstring>
#include <string>

namespace airis::engine {
namespace {

// libpng and libjpeg report errors by longjmp. The functions that call them with a jump target
// set (RunPngReadHeader, RunPngReadRows, RunJpegRead) hold no object with a destructor of their
// own: what they fill is owned by their callers, so a jump leaks nothing.

struct PngIo {
  std::span<const std::uint8_t> in;  // the file, and how far it has been read
  std::size_t read = 0;
  char error[256] = {};
};

void OnPngError(png_structp png, png_const_charp message) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  std::snprintf(io->error, sizeof io->error, "%s", message);
  png_longjmp(png, 1);
}

void OnPngWarning(png_structp, png_const_charp) {}  // nothing airis writes or checks needs them

void ReadFromSpan(png_structp png, png_bytep data, png_size_t n) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (io->in.size() - io->read < n) png_error(png, "the file ends inside the image");
  std::memcpy(data, io->in.data() + io->read, n);
  io->read += n;
}

// What a read should give: the PNG as stored, or 8-bit RGBA whatever it stores.
enum class PngReadAs { kStored, kRgba8 };

struct PngHeader {
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  int bit_depth = 0;
  int color_type = 0;
};

// Reads the header, sets the transforms of `as` and returns the header; the caller sizes the rows.
bool RunPngReadHeader(png_structp png, png_infop info, PngIo* io, PngReadAs as, PngHeader* h) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, io, ReadFromSpan);
  // Width and height as libpng allows by default (1,000,000); the texture and dataset readers
  // check their own limits before decoding.
  png_read_info(png, info);
  int interlace = 0;
  png_get_IHDR(png, info, &h->width, &h->height, &h->bit_depth, &h->color_type, &interlace, nullptr,
               nullptr);
  if (interlace != PNG_INTERLACE_NONE) png_set_interlace_handling(png);
  if (as == PngReadAs::kRgba8) {
    if (h->color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (h->color_type == PNG_COLOR_TYPE_GRAY && h->bit_depth < 8) {
      png_set_expand_gray_1_2_4_to_8(png);
    }
    if (h->bit_depth == 16) png_set_strip_16(png);
    if (h->color_type == PNG_COLOR_TYPE_GRAY || h->color_type == PNG_COLOR_TYPE_GRAY_ALPHA) {
      png_set_gray_to_rgb(png);
    }
    if (h->color_type & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
    png_set_filler(png, 0xff, PNG_FILLER_AFTER);
  } else if (h->bit_depth == 16) {
    png_set_swap(png);  // to native little-endian samples
  }
  png_read_update_info(png, info);
  return true;
}

bool RunPngReadRows(png_structp png, png_infop info, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, info);
  return true;
}

std::string PngMessage(const PngIo& io, const char* fallback) {
  return io.error[0] ? std::string("PNG: ") + io.error : std::string(fallback);
}

// The layout a stored PNG is read as, if it is one of those written by airis.
bool StoredLayout(const PngHeader& h, PngLayout* layout) {
  if (h.color_type == PNG_COLOR_TYPE_GRAY && h.bit_depth == 8)
    *layout = PngLayout::kGray8;
  else if (h.color_type == PNG_COLOR_TYPE_GRAY && h.bit_depth == 16)
    *layout = PngLayout::kGray16;
  else if (h.color_type == PNG_COLOR_TYPE_RGB && h.bit_depth == 8)
    *layout = PngLayout::kRgb8;
  else if (h.color_type == PNG_COLOR_TYPE_RGBA && h.bit_depth == 8)
    *layout = PngLayout::kRgba8;
  else
    return false;
  return true;
}

class PngReader {
 public:
  explicit PngReader(std::span<const std::uint8_t> bytes) {
    io_.in = bytes;
    png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &io_, OnPngError, OnPngWarning);
    if (png_) info_ = png_create_info_struct(png_);
    if (!png_ || !info_) throw ImageCodecError("PNG: out of memory");
  }
  ~PngReader() { png_destroy_read_struct(&png_, &info_, nullptr); }
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;

  PngHeader ReadHeader(PngReadAs as) {
    if (io_.in.size() < 8 || png_sig_cmp(io_.in.data(), 0, 8) != 0) {
      throw ImageCodecError("not a PNG file");
    }
    PngHeader h;
    if (!RunPngReadHeader(png_, info_, &io_, as, &h)) {
      throw ImageCodecError(PngMessage(io_, "PNG: cannot read the header"));
    }
    return h;
  }

  // Reads the rows into `pixels`, whose rows are `row_bytes` apart.
  void ReadRows(std::uint8_t* pixels, std::size_t row_bytes, png_uint_32 height) {
    if (png_get_rowbytes(png_, info_) != row_bytes) throw ImageCodecError("PNG: unexpected layout");
    std::vector<png_bytep> rows(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = pixels + y * row_bytes;
    if (!RunPngReadRows(png_, info_, rows.data())) {
      throw ImageCodecError(PngMessage(io_, "PNG: cannot read the image"));
    }
  }

 private:
  PngIo io_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

// JPEG through libjpeg's classic interface.
struct JpegErrors {
  jpeg_error_mgr pub;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX] = {};
};

void OnJpegError(j_common_ptr cinfo) {
  auto* errors = reinterpret_cast<JpegErrors*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, errors->message);
  std::longjmp(errors->jump, 1);
}

void OnJpegMessage(j_common_ptr, int) {}  // warnings (a corrupt stream is still an error above)

// Decodes into `out` (sized here) as RGBA8; false with errors->message set on failure.
bool RunJpegRead(jpeg_decompress_struct* cinfo, JpegErrors* errors,
                 std::span<const std::uint8_t> bytes, Image<std::uint8_t>* out) {
  if (setjmp(errors->jump)) return false;
  jpeg_mem_src(cinfo, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(cinfo, TRUE);
  cinfo->out_color_space = JCS_EXT_RGBA;  // libjpeg-turbo: grey and YCbCr alike, alpha 255
  jpeg_start_decompress(cinfo);
  out->Resize(static_cast<int>(cinfo->output_width), static_cast<int>(cinfo->output_height), 4);
  const std::size_t row_bytes = std::size_t{cinfo->output_width} * 4;
  while (cinfo->output_scanline < cinfo->output_height) {
    JSAMPROW row = out->pixels.data() + cinfo->output_scanline * row_bytes;
    jpeg_read_scanlines(cinfo, &row, 1);
  }
  jpeg_finish_decompress(cinfo);
  return true;
}

Image<std::uint8_t> DecodeJpegRgba8(std::span<const std::uint8_t> bytes) {
  jpeg_decompress_struct cinfo;
  JpegErrors errors;
  cinfo.err = jpeg_std_error(&errors.pub);
  errors.pub.error_exit = OnJpegError;
  errors.pub.emit_message = OnJpegMessage;
  jpeg_create_decompress(&cinfo);
  Image<std::uint8_t> out;
  const bool ok = RunJpegRead(&cinfo, &errors, bytes, &out);
  jpeg_destroy_decompress(&cinfo);
  if (!ok) throw ImageCodecError(std::string("JPEG: ") + errors.message);
  return out;
}

}  // namespace

int PngChannels(PngLayout layout) {
  switch (layout) {
    case PngLayout::kGray8:
    case PngLayout::kGray16:
      return 1;
    case PngLayout::kRgb8:
      return 3;
    case PngLayout::kRgba8:
      return 4;
  }
  return 1;
}

PngPixels DecodePng(std::span<const std::uint8_t> bytes) {
  PngReader reader(bytes);
  const PngHeader h = reader.ReadHeader(PngReadAs::kStored);
  PngPixels out;
  if (!StoredLayout(h, &out.layout)) {
    throw ImageCodecError("PNG: " + std::to_string(h.bit_depth) + "-bit samples of colour type " +
                          std::to_string(h.color_type) +
                          " (airis reads 8-bit grey, RGB and RGBA and 16-bit grey)");
  }
  out.width = static_cast<int>(h.width);
  out.height = static_cast<int>(h.height);
  const std::size_t samples = std::size_t(h.width) * h.height * PngChannels(out.layout);
  const std::size_t row_samples = std::size_t(h.width) * PngChannels(out.layout);
  if (out.layout == PngLayout::kGray16) {
    out.samples16.resize(samples);
    reader.ReadRows(reinterpret_cast<std::uint8_t*>(out.samples16.data()), row_samples * 2,
                    h.height);
  } else {
    out.samples8.resize(samples);
    reader.ReadRows(out.samples8.data(), row_samples, h.height);
  }
  return out;
}

Image<std::uint8_t> DecodeImageRgba8(std::span<const std::uint8_t> bytes) {
  if (bytes.size() >= 2 && bytes[0] == 0xff && bytes[1] == 0xd8) return DecodeJpegRgba8(bytes);
  PngReader reader(bytes);
  const PngHeader h = reader.ReadHeader(PngReadAs::kRgba8);
  Image<std::uint8_t> out;
  out.Resize(static_cast<int>(h.width), static_cast<int>(h.height), 4);
  reader.ReadRows(out.pixels.data(), std::size_t(h.width) * 4, h.height);
  return out;
}

}  // namespace airis::engine
