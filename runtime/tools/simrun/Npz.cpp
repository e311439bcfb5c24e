//===- Npz.cpp - .npy arrays and .npz archives of them --------------------===//

#include "Npz.h"

#include "Options.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <unistd.h>

#include <minizip/zip.h>

namespace simrun {

std::string npyHeader(const std::string &descr,
                      const std::vector<int64_t> &shape) {
  std::string dims;
  for (int64_t extent : shape)
    dims += std::to_string(extent) + ", ";
  // A 1-d shape keeps its comma, "(5,)"; others drop the last ", ".
  if (shape.size() > 1)
    dims.resize(dims.size() - 2);
  else if (shape.size() == 1)
    dims.resize(dims.size() - 1);
  std::string header = "{'descr': '" + descr +
                       "', 'fortran_order': False, 'shape': (" + dims + "), }";
  // Magic, version, length and header end on a multiple of 64 bytes.
  size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  std::string file("\x93NUMPY\x01\x00", 8);
  file += char(header.size() & 0xff);
  file += char(header.size() >> 8);
  return file + header;
}

std::string floatDescr(int32_t scalarBytes) {
  return "<f" + std::to_string(scalarBytes);
}

std::string npyFile(const std::string &descr, const std::vector<int64_t> &shape,
                    std::string_view data) {
  return npyHeader(descr, shape) + std::string(data);
}

std::string npyString(std::string_view text) {
  std::vector<uint32_t> points;
  for (size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    int length = c < 0x80           ? 1
                 : (c >> 5) == 0x6  ? 2
                 : (c >> 4) == 0xE  ? 3
                 : (c >> 3) == 0x1E ? 4
                                    : 0;
    uint32_t point = length == 1   ? c
                     : length == 2 ? c & 0x1F
                     : length == 3 ? c & 0x0F
                                   : c & 0x07;
    bool valid = length > 0 && i + size_t(length) <= text.size();
    for (int k = 1; valid && k < length; ++k) {
      unsigned char next = static_cast<unsigned char>(text[i + size_t(k)]);
      valid = (next & 0xC0) == 0x80;
      point = (point << 6) | (next & 0x3F);
    }
    // Overlong forms, surrogates and points past U+10FFFF are not UTF-8.
    static const uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    valid = valid && point >= smallest[length] && point <= 0x10FFFF &&
            (point < 0xD800 || point > 0xDFFF);
    points.push_back(valid ? point : 0xFFFD);
    i += valid ? size_t(length) : 1;
  }
  // numpy.array("") is '<U1' holding one zero code point.
  if (points.empty())
    points.push_back(0);
  std::string data;
  for (uint32_t point : points)
    for (int byte = 0; byte < 4; ++byte)
      data += char((point >> (8 * byte)) & 0xff);
  return npyFile("<U" + std::to_string(points.size()), {}, data);
}

//===----------------------------------------------------------------------===//
// The zip container
//===----------------------------------------------------------------------===//

namespace {

/// minizip's file functions over a descriptor that is already open.
struct Descriptor {
  int fd;
  int error = 0;
};

voidpf openFd(voidpf opaque, const void *, int) { return opaque; }

uLong readFd(voidpf, voidpf stream, void *buffer, uLong size) {
  auto *file = static_cast<Descriptor *>(stream);
  ssize_t done;
  do
    done = ::read(file->fd, buffer, size);
  while (done < 0 && errno == EINTR);
  if (done < 0) {
    file->error = errno;
    return 0;
  }
  return uLong(done);
}

uLong writeFd(voidpf, voidpf stream, const void *buffer, uLong size) {
  auto *file = static_cast<Descriptor *>(stream);
  const char *data = static_cast<const char *>(buffer);
  uLong left = size;
  while (left > 0) {
    ssize_t done = ::write(file->fd, data, left);
    if (done < 0 && errno == EINTR)
      continue;
    if (done <= 0) {
      file->error = done < 0 ? errno : EIO;
      return size - left;
    }
    data += done;
    left -= uLong(done);
  }
  return size;
}

ZPOS64_T tellFd(voidpf, voidpf stream) {
  auto *file = static_cast<Descriptor *>(stream);
  off_t at = lseek(file->fd, 0, SEEK_CUR);
  if (at < 0) {
    file->error = errno;
    return ZPOS64_T(-1);
  }
  return ZPOS64_T(at);
}

long seekFd(voidpf, voidpf stream, ZPOS64_T offset, int origin) {
  auto *file = static_cast<Descriptor *>(stream);
  int whence = origin == ZLIB_FILEFUNC_SEEK_CUR   ? SEEK_CUR
               : origin == ZLIB_FILEFUNC_SEEK_END ? SEEK_END
                                                  : SEEK_SET;
  if (lseek(file->fd, off_t(offset), whence) < 0) {
    file->error = errno;
    return -1;
  }
  return 0;
}

/// The descriptor belongs to the caller, who syncs and closes it.
int closeFd(voidpf, voidpf) { return 0; }

int errorFd(voidpf, voidpf stream) {
  return static_cast<Descriptor *>(stream)->error;
}

} // namespace

void writeNpz(int fd, const std::vector<NpzArray> &arrays,
              const std::string &name) {
  Descriptor file{fd};
  zlib_filefunc64_def functions = {openFd, readFd,  writeFd, tellFd,
                                   seekFd, closeFd, errorFd, &file};
  auto fail = [&](const std::string &what) {
    runError("cannot write '" + name + "' (" + what + ")" +
             (file.error ? std::string(": ") + std::strerror(file.error)
                         : std::string()));
  };
  zipFile zip = zipOpen2_64(nullptr, APPEND_STATUS_CREATE, nullptr, &functions);
  if (!zip)
    fail("zipOpen");
  // 1980-01-01, the zip format's first day: no time of writing in the file.
  zip_fileinfo info = {};
  info.tmz_date.tm_mday = 1;
  info.tmz_date.tm_year = 1980;
  try {
    for (const NpzArray &array : arrays) {
      uint64_t bytes = array.header.size();
      for (std::string_view piece : array.pieces)
        bytes += piece.size();
      std::string entry = array.key + ".npy";
      // Zip64 only where the 32-bit sizes and offsets do not reach.
      int zip64 = bytes >= 0xffffffffu ? 1 : 0;
      if (zipOpenNewFileInZip64(zip, entry.c_str(), &info, nullptr, 0, nullptr,
                                0, nullptr, 0 /* stored */, 0, zip64) != ZIP_OK)
        fail("zipOpenNewFileInZip64 of '" + entry + "'");
      auto put = [&](std::string_view data) {
        while (!data.empty()) {
          size_t chunk = std::min<size_t>(data.size(), size_t(1) << 30);
          if (zipWriteInFileInZip(zip, data.data(), unsigned(chunk)) != ZIP_OK)
            fail("zipWriteInFileInZip of '" + entry + "'");
          data.remove_prefix(chunk);
        }
      };
      put(array.header);
      for (std::string_view piece : array.pieces)
        put(piece);
      if (zipCloseFileInZip(zip) != ZIP_OK)
        fail("zipCloseFileInZip of '" + entry + "'");
    }
  } catch (...) {
    zipClose(zip, nullptr);
    throw;
  }
  if (zipClose(zip, nullptr) != ZIP_OK)
    fail("zipClose");
}

} // namespace simrun
