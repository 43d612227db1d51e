#pragma once
// A thin RAII layer over the HDF5 C API: only what the study store needs (groups, scalar attributes, 1-D/2-D
// double datasets, string lists). Every call is checked; failures throw std::runtime_error naming the object.
// HDF5's own error stack printing is switched off by study::init_libraries(), so a failed open is our message,
// not a page of noise.
// The Debian build of HDF5 is not thread-safe: callers serialise all use through h5::lock().
#include <hdf5.h>

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <variant>
#include <vector>

namespace dpdrng::study::h5 {

std::mutex& lock();

// Owns one hid_t and closes it with the matching H5*close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer close, const std::string& what);  // throws if id < 0
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle& operator=(Handle&& o) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle();
  hid_t id() const { return id_; }
  explicit operator bool() const { return id_ >= 0; }

 private:
  hid_t id_ = -1;
  Closer close_ = nullptr;
};

// An unsigned integer is written as HDF5's unsigned 64-bit type (seeds use the whole range); a signed one as int64.
using Attribute = std::variant<double, std::int64_t, std::uint64_t, std::string>;

struct Matrix {
  std::size_t rows = 0, cols = 0;
  std::vector<double> data;  // row-major
};

// A file held in memory (HDF5's core driver, no backing store): HDF5 writes nothing to disk, so a full disk can
// never fail one of its calls half-way and leave the library with a file it cannot close. Every file the store
// writes is built this way, and image() hands its bytes to the one checked writer (write_file_atomically).
// A user block (0, or a power of two >= 512) is space before the HDF5 data that HDF5 leaves alone.
Handle create_memory_file(std::size_t userblock = 0);
// The whole file as it would be on disk, user block included (flushed first).
std::string image(hid_t file);

// Truncates. A user block (0, or a power of two >= 512) is space before the HDF5 data that HDF5 leaves alone.
Handle create_file(const std::string& path, std::size_t userblock = 0);
Handle open_file(const std::string& path, bool writable = false);
Handle create_group(hid_t parent, const std::string& name);
Handle open_group(hid_t parent, const std::string& name);
bool exists(hid_t parent, const std::string& name);

void write_attribute(hid_t obj, const std::string& name, const Attribute& value);
std::map<std::string, Attribute> read_attributes(hid_t obj);
// An attribute of the dataset or group `name` under `parent` (a dataset's unit).
void write_attribute(hid_t parent, const std::string& name, const std::string& attribute, const Attribute& value);
std::map<std::string, Attribute> read_attributes(hid_t parent, const std::string& name);

// `integer`: stored as int64 (the caller has checked that every value is a whole number that a double holds
// exactly); read back as doubles, the values are the same.
void write_series(hid_t group, const std::string& name, const std::vector<double>& values, bool integer = false);
void write_matrix(hid_t group, const std::string& name, const Matrix& m, bool integer = false);
void write_strings(hid_t group, const std::string& name, const std::vector<std::string>& values);

// Names of the links (groups or datasets) directly under a group, in name order.
std::vector<std::string> list(hid_t group);
bool is_group(hid_t parent, const std::string& name);
// A dataset's rank and shape, then its contents; doubles are read for any numeric type.
std::vector<hsize_t> shape(hid_t group, const std::string& name);
bool is_string_dataset(hid_t group, const std::string& name);
std::vector<double> read_doubles(hid_t group, const std::string& name);
std::vector<std::string> read_strings(hid_t group, const std::string& name);

// Copies an object (with everything under it) from one file into another: how cells are assembled.
void copy(hid_t src_loc, const std::string& src_name, hid_t dst_loc, const std::string& dst_name);
void flush(hid_t file);

}  // namespace dpdrng::study::h5
