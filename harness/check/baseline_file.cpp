#include "harness/check/baseline_file.hpp"
#include "cases/util/input_error.hpp"

#include "cases/util/atomic_file.hpp"

#include <zlib.h>

#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace tritri {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// windowBits 15 + 16: a gzip stream (header and CRC) rather than a bare zlib one, so the file
// is readable with gzip/zcat too; + 32 on reading also accepts a zlib stream.
constexpr int kGzipWindow = 15 + 16;

std::string gunzip(const std::string& data, const std::string& path) {
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) throw std::runtime_error(path + ": cannot start decompression");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  std::string out;
  char buffer[1 << 16];
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    z.next_out = reinterpret_cast<Bytef*>(buffer);
    z.avail_out = sizeof buffer;
    status = inflate(&z, Z_NO_FLUSH);
    if (status != Z_OK && status != Z_STREAM_END) {
      inflateEnd(&z);
      throw InputError(path + ": corrupt gzip data (" + (z.msg ? z.msg : "inflate failed") + ")");
    }
    out.append(buffer, sizeof buffer - z.avail_out);
    if (status == Z_OK && z.avail_in == 0 && z.avail_out != 0) {
      inflateEnd(&z);
      throw InputError(path + ": truncated gzip data");
    }
  }
  inflateEnd(&z);
  return out;
}

std::string gzip(const std::string& data) {
  z_stream z{};
  if (deflateInit2(&z, 9, Z_DEFLATED, kGzipWindow, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("cannot start gzip compression");
  std::string out(deflateBound(&z, static_cast<uLong>(data.size())) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, Z_FINISH);
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw std::runtime_error("gzip compression failed");
  out.resize(z.total_out);
  return out;
}

}  // namespace

std::string read_possibly_gzipped(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open baseline for reading");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const bool gzipped = data.size() >= 2 && static_cast<unsigned char>(data[0]) == 0x1f &&
                       static_cast<unsigned char>(data[1]) == 0x8b;
  return gzipped ? gunzip(data, path) : data;
}

void write_baseline_file(const std::string& path, const Baseline& baseline) {
  std::ostringstream text;
  write_baseline(text, baseline);
  const std::string bytes = ends_with(path, ".gz") ? gzip(text.str()) : text.str();
  write_file_atomically(path, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

}  // namespace tritri
