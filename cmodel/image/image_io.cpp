#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <png.h>

#include "common/error.hpp"
#include "image/image.hpp"

namespace cig {

Image concatenate_horizontally(const std::vector<const Image*>& parts) {
  int w = 0, h = parts.empty() ? 0 : parts[0]->height;
  for (const Image* p : parts) {
    if (p->height != h) throw std::runtime_error("panorama: channel images differ in height");
    w += p->width;
  }
  Image out(w, h);
  int x0 = 0;
  for (const Image* p : parts) {
    for (int y = 0; y < h; ++y) std::memcpy(out.at(x0, y), p->at(0, y), std::size_t(p->width) * 3);
    x0 += p->width;
  }
  return out;
}

namespace {

// Writes through a temporary file in the same directory, then renames it into place.
template <class Writer>
void write_atomically(const std::string& file, Writer&& writer) {
  // The folder is created with the file (the commands checked that it can be, before any work).
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  const std::string tmp = file + ".tmp";
  try {
    writer(tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error(file + ": cannot write (" + ec.message() + ")");
  }
}

}  // namespace

void write_text_file(const std::string& file, const std::string& text) {
  write_atomically(file, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(file + ": cannot write");
  });
}

void write_png(const std::string& file, const Image& img) {
  write_atomically(file, [&](const std::string& tmp) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(img.width);
    image.height = png_uint_32(img.height);
    image.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_file(&image, tmp.c_str(), 0, img.rgb.data(), img.width * 3, nullptr))
      throw std::runtime_error(file + ": cannot write PNG (" + image.message + ")");
  });
}

Image read_png(const std::string& file) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, file.c_str()))
    throw InputError(file, "", std::string("cannot read PNG (") + image.message + ")");
  image.format = PNG_FORMAT_RGB;
  Image img(int(image.width), int(image.height));
  if (!png_image_finish_read(&image, nullptr, img.rgb.data(), int(image.width) * 3, nullptr))
    throw InputError(file, "", std::string("cannot decode PNG (") + image.message + ")");
  return img;
}

void write_ids(const std::string& file, const IdBuffer& ids) {
  write_atomically(file, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << "CIGIDS1 " << ids.width << " " << ids.height << "\n";
    std::vector<unsigned char> bytes(ids.id.size() * 4);
    for (std::size_t i = 0; i < ids.id.size(); ++i) {
      const std::uint32_t v = std::uint32_t(ids.id[i]);
      bytes[4 * i + 0] = (unsigned char)(v & 0xff);
      bytes[4 * i + 1] = (unsigned char)((v >> 8) & 0xff);
      bytes[4 * i + 2] = (unsigned char)((v >> 16) & 0xff);
      bytes[4 * i + 3] = (unsigned char)((v >> 24) & 0xff);
    }
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    out.close();
    if (!out) throw std::runtime_error(file + ": cannot write");
  });
}

IdBuffer read_ids(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "", "cannot open file (missing or unreadable)");
  std::string magic;
  int w = 0, h = 0;
  in >> magic >> w >> h;
  if (magic != "CIGIDS1" || w <= 0 || h <= 0 || w > 65536 || h > 65536 || in.get() != '\n')
    throw InputError(file, "header", "not a CIGIDS1 id file");
  IdBuffer ids(w, h);
  std::vector<unsigned char> bytes(ids.id.size() * 4);
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (in.gcount() != std::streamsize(bytes.size())) throw InputError(file, "data", "id file is truncated");
  for (std::size_t i = 0; i < ids.id.size(); ++i)
    ids.id[i] = std::int32_t(std::uint32_t(bytes[4 * i]) | std::uint32_t(bytes[4 * i + 1]) << 8 |
                             std::uint32_t(bytes[4 * i + 2]) << 16 | std::uint32_t(bytes[4 * i + 3]) << 24);
  return ids;
}

}  // namespace cig
