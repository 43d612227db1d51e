#include "dpdrng/study/h5.hpp"

#include <stdexcept>

namespace dpdrng::study::h5 {
namespace {


void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

Handle vlen_string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(t.id(), H5T_VARIABLE), "set string size");
  check(H5Tset_cset(t.id(), H5T_CSET_UTF8), "set string charset");
  return t;
}

Handle link_creation_plist() {
  // Intermediate groups are created on demand, so "a/b" works in one call.
  Handle p(H5Pcreate(H5P_LINK_CREATE), H5Pclose, "link plist");
  check(H5Pset_create_intermediate_group(p.id(), 1), "intermediate groups");
  return p;
}

std::string read_string_attr(hid_t attr, hid_t type) {
  if (H5Tis_variable_str(type) > 0) {
    Handle mem = vlen_string_type();
    char* s = nullptr;
    check(H5Aread(attr, mem.id(), &s), "read string attribute");
    std::string out = s ? s : "";
    H5free_memory(s);
    return out;
  }
  const std::size_t n = H5Tget_size(type);
  std::string out(n, '\0');
  Handle mem(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(mem.id(), n), "set string size");
  check(H5Aread(attr, mem.id(), out.data()), "read string attribute");
  out.resize(out.find('\0') == std::string::npos ? n : out.find('\0'));
  return out;
}

herr_t collect_attr(hid_t obj, const char* name, const H5A_info_t*, void* data) {
  auto& out = *static_cast<std::map<std::string, Attribute>*>(data);
  try {
    Handle a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, std::string("attribute ") + name);
    Handle t(H5Aget_type(a.id()), H5Tclose, "attribute type");
    switch (H5Tget_class(t.id())) {
      case H5T_FLOAT: {
        double v = 0;
        check(H5Aread(a.id(), H5T_NATIVE_DOUBLE, &v), "read attribute");
        out[name] = v;
        break;
      }
      case H5T_INTEGER: {
        if (H5Tget_sign(t.id()) == H5T_SGN_NONE && H5Tget_size(t.id()) == 8) {
          std::uint64_t v = 0;
          check(H5Aread(a.id(), H5T_NATIVE_UINT64, &v), "read attribute");
          out[name] = v;
        } else {
          std::int64_t v = 0;
          check(H5Aread(a.id(), H5T_NATIVE_INT64, &v), "read attribute");
          out[name] = v;
        }
        break;
      }
      case H5T_STRING: out[name] = read_string_attr(a.id(), t.id()); break;
      default: break;  // not ours: ignored
    }
  } catch (const std::exception&) {
    return -1;
  }
  return 0;
}

}  // namespace

std::mutex& lock() {
  static std::mutex m;
  return m;
}

Handle::Handle(hid_t id, Closer close, const std::string& what) : id_(id), close_(close) {
  if (id < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

Handle& Handle::operator=(Handle&& o) noexcept {
  if (this != &o) {
    if (id_ >= 0 && close_) close_(id_);
    id_ = o.id_;
    close_ = o.close_;
    o.id_ = -1;
  }
  return *this;
}

Handle::~Handle() {
  if (id_ >= 0 && close_) close_(id_);
}

Handle create_file(const std::string& path, std::size_t userblock) {
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose, "file creation plist");
  if (userblock > 0) check(H5Pset_userblock(fcpl.id(), userblock), "set user block");
  return Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.id(), H5P_DEFAULT), H5Fclose, "create " + path);
}

Handle create_memory_file(std::size_t userblock) {
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose, "file creation plist");
  if (userblock > 0) check(H5Pset_userblock(fcpl.id(), userblock), "set user block");
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access plist");
  check(H5Pset_fapl_core(fapl.id(), std::size_t{1} << 16, 0), "in-memory driver");
  // The name only identifies the file among those open in this process.
  static unsigned long serial = 0;
  const std::string name = "dpdrng-memory-" + std::to_string(++serial) + ".h5";
  return Handle(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, fcpl.id(), fapl.id()), H5Fclose, "create in memory");
}

std::string image(hid_t file) {
  flush(file);
  const ssize_t n = H5Fget_file_image(file, nullptr, 0);
  if (n < 0) throw std::runtime_error("HDF5: file image failed");
  std::string out(static_cast<std::size_t>(n), '\0');
  if (n > 0 && H5Fget_file_image(file, out.data(), out.size()) != n) throw std::runtime_error("HDF5: file image failed");
  // HDF5 1.10's image starts at the superblock, leaving the user block out: it is put back (zeros, for the
  // caller to fill), so that the bytes are those of the file on disk whichever way the library hands them over.
  Handle fcpl(H5Fget_create_plist(file), H5Pclose, "file creation plist");
  hsize_t userblock = 0;
  check(H5Pget_userblock(fcpl.id(), &userblock), "user block size");
  static constexpr char kSignature[] = "\x89HDF\r\n\x1a\n";
  if (userblock > 0 && out.compare(0, 8, kSignature, 8) == 0) out.insert(0, static_cast<std::size_t>(userblock), '\0');
  return out;
}

Handle open_file(const std::string& path, bool writable) {
  return Handle(H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                "open " + path);
}

Handle create_group(hid_t parent, const std::string& name) {
  Handle lcpl = link_creation_plist();
  return Handle(H5Gcreate2(parent, name.c_str(), lcpl.id(), H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                "create group " + name);
}

Handle open_group(hid_t parent, const std::string& name) {
  return Handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, "open group " + name);
}

bool exists(hid_t parent, const std::string& name) {
  const htri_t r = H5Lexists(parent, name.c_str(), H5P_DEFAULT);
  return r > 0;
}

void write_attribute(hid_t obj, const std::string& name, const Attribute& value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  if (H5Aexists(obj, name.c_str()) > 0) check(H5Adelete(obj, name.c_str()), "replace attribute " + name);
  if (const auto* d = std::get_if<double>(&value)) {
    Handle a(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
             "attribute " + name);
    check(H5Awrite(a.id(), H5T_NATIVE_DOUBLE, d), "write attribute " + name);
  } else if (const auto* i = std::get_if<std::int64_t>(&value)) {
    Handle a(H5Acreate2(obj, name.c_str(), H5T_STD_I64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
             "attribute " + name);
    check(H5Awrite(a.id(), H5T_NATIVE_INT64, i), "write attribute " + name);
  } else if (const auto* u = std::get_if<std::uint64_t>(&value)) {
    Handle a(H5Acreate2(obj, name.c_str(), H5T_STD_U64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
             "attribute " + name);
    check(H5Awrite(a.id(), H5T_NATIVE_UINT64, u), "write attribute " + name);
  } else {
    Handle t = vlen_string_type();
    Handle a(H5Acreate2(obj, name.c_str(), t.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
             "attribute " + name);
    const char* s = std::get<std::string>(value).c_str();
    check(H5Awrite(a.id(), t.id(), &s), "write attribute " + name);
  }
}

std::map<std::string, Attribute> read_attributes(hid_t obj) {
  std::map<std::string, Attribute> out;
  hsize_t idx = 0;
  check(H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, &idx, collect_attr, &out), "read attributes");
  return out;
}

void write_attribute(hid_t parent, const std::string& name, const std::string& attribute, const Attribute& value) {
  Handle o(H5Oopen(parent, name.c_str(), H5P_DEFAULT), H5Oclose, "open " + name);
  write_attribute(o.id(), attribute, value);
}

std::map<std::string, Attribute> read_attributes(hid_t parent, const std::string& name) {
  Handle o(H5Oopen(parent, name.c_str(), H5P_DEFAULT), H5Oclose, "open " + name);
  return read_attributes(o.id());
}

void write_series(hid_t group, const std::string& name, const std::vector<double>& values, bool integer) {
  write_matrix(group, name, Matrix{values.size(), 0, values}, integer);
}

void write_matrix(hid_t group, const std::string& name, const Matrix& m, bool integer) {
  // cols == 0 marks a 1-D series.
  const int rank = m.cols == 0 ? 1 : 2;
  const hsize_t dims[2] = {m.rows, m.cols};
  if (m.data.size() != (rank == 1 ? m.rows : m.rows * m.cols))
    throw std::runtime_error("dataset " + name + ": shape does not match its data");
  Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose, "dataspace " + name);
  Handle lcpl = link_creation_plist();
  Handle d(H5Dcreate2(group, name.c_str(), integer ? H5T_STD_I64LE : H5T_IEEE_F64LE, space.id(), lcpl.id(),
                      H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose, "create dataset " + name);
  if (m.data.empty()) return;
  if (integer) {
    const std::vector<std::int64_t> whole(m.data.begin(), m.data.end());
    check(H5Dwrite(d.id(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, whole.data()), "write " + name);
  } else {
    check(H5Dwrite(d.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, m.data.data()), "write " + name);
  }
}

void write_strings(hid_t group, const std::string& name, const std::vector<std::string>& values) {
  const hsize_t dims[1] = {values.size()};
  Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose, "dataspace " + name);
  Handle t = vlen_string_type();
  Handle lcpl = link_creation_plist();
  Handle d(H5Dcreate2(group, name.c_str(), t.id(), space.id(), lcpl.id(), H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
           "create dataset " + name);
  std::vector<const char*> ptrs;
  for (const auto& s : values) ptrs.push_back(s.c_str());
  if (!ptrs.empty()) check(H5Dwrite(d.id(), t.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()), "write " + name);
}

std::vector<std::string> list(hid_t group) {
  // By index rather than H5Literate, whose callback signature changed between HDF5 1.10 and 1.12.
  H5G_info_t info;
  check(H5Gget_info(group, &info), "list group");
  std::vector<std::string> names;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t n = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (n < 0) throw std::runtime_error("HDF5: list group failed");
    std::string name(static_cast<std::size_t>(n) + 1, '\0');
    if (H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(), H5P_DEFAULT) < 0)
      throw std::runtime_error("HDF5: list group failed");
    name.resize(static_cast<std::size_t>(n));
    names.push_back(std::move(name));
  }
  return names;
}

bool is_group(hid_t parent, const std::string& name) {
  Handle o(H5Oopen(parent, name.c_str(), H5P_DEFAULT), H5Oclose, "open " + name);
  return H5Iget_type(o.id()) == H5I_GROUP;
}

std::vector<hsize_t> shape(hid_t group, const std::string& name) {
  Handle d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  Handle s(H5Dget_space(d.id()), H5Sclose, "dataspace " + name);
  const int rank = H5Sget_simple_extent_ndims(s.id());
  if (rank < 0) throw std::runtime_error("HDF5: rank of " + name);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) check(H5Sget_simple_extent_dims(s.id(), dims.data(), nullptr), "shape of " + name);
  return dims;
}

bool is_string_dataset(hid_t group, const std::string& name) {
  Handle d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  Handle t(H5Dget_type(d.id()), H5Tclose, "type of " + name);
  return H5Tget_class(t.id()) == H5T_STRING;
}

std::vector<double> read_doubles(hid_t group, const std::string& name) {
  std::size_t n = 1;
  for (hsize_t k : shape(group, name)) n *= k;
  std::vector<double> out(n);
  Handle d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  if (n > 0) check(H5Dread(d.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  return out;
}

std::vector<std::string> read_strings(hid_t group, const std::string& name) {
  const auto dims = shape(group, name);
  const std::size_t n = dims.empty() ? 1 : dims[0];
  Handle d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  Handle t = vlen_string_type();
  std::vector<char*> ptrs(n, nullptr);
  if (n > 0) check(H5Dread(d.id(), t.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()), "read " + name);
  std::vector<std::string> out;
  for (char* p : ptrs) {
    out.emplace_back(p ? p : "");
    H5free_memory(p);
  }
  return out;
}

void copy(hid_t src_loc, const std::string& src_name, hid_t dst_loc, const std::string& dst_name) {
  Handle lcpl = link_creation_plist();
  check(H5Ocopy(src_loc, src_name.c_str(), dst_loc, dst_name.c_str(), H5P_DEFAULT, lcpl.id()),
        "copy " + src_name + " to " + dst_name);
}

void flush(hid_t file) { check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush"); }

}  // namespace dpdrng::study::h5
