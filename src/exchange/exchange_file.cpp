#include "exchange/exchange_file.hpp"

#include "exchange/problem_description.hpp"
#include "dlpverify/errors.hpp"
#include "io/input_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <hdf5.h>
#include <unistd.h>

namespace dlpverify::exchange {

namespace {

// An HDF5 identifier closed when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// HDF5 prints its error stack to stderr by default; a file of garbage must cost one line of ours.
void quiet_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// Members per chunk: whole columns go out in a few large chunks (8 MiB), never member by member.
constexpr hsize_t kChunkMembers = hsize_t{1} << 20;

class Writer {
 public:
  explicit Writer(std::string path) : path_(std::move(path)) {}

  void require(bool ok, const std::string& what) const {
    if (!ok) throw ExchangeError("cannot write the exchange file " + path_ + ": " + what);
  }

  void number(hid_t at, const std::string& name, double value) const {
    attribute(at, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
  }
  void integer(hid_t at, const std::string& name, long long value) const {
    attribute(at, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, &value);
  }
  // A UTF-8 variable-length string (h5py reads it as str), or a list of them.
  void text(hid_t at, const std::string& name, const std::string& value) const { texts(at, name, {value}, true); }
  void texts(hid_t at, const std::string& name, const std::vector<std::string>& values, bool scalar = false) const {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    require(type.valid() && H5Tset_size(type, H5T_VARIABLE) >= 0 && H5Tset_cset(type, H5T_CSET_UTF8) >= 0,
            "string type");
    std::vector<const char*> pointers;
    for (const std::string& v : values) pointers.push_back(v.c_str());
    const hsize_t count = values.size();
    Handle space(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose);
    Handle a(H5Acreate2(at, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    require(space.valid() && a.valid() && H5Awrite(a, type, pointers.data()) >= 0, "attribute " + name);
  }

  // A float64 column of `count` values, chunked, written in one call.
  void column(hid_t group, const std::string& name, const double* values, hsize_t count, const std::string& unit) const {
    Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose);
    Handle create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    const hsize_t chunk = std::max<hsize_t>(1, std::min(count, kChunkMembers));
    require(space.valid() && create.valid() && H5Pset_chunk(create, 1, &chunk) >= 0, "dataset " + name);
    Handle set(H5Dcreate2(group, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, create, H5P_DEFAULT), H5Dclose);
    require(set.valid() && H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) >= 0,
            "dataset " + name);
    text(set, "unit", unit);
  }

 private:
  void attribute(hid_t at, const std::string& name, hid_t file_type, hid_t memory_type, const void* value) const {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle a(H5Acreate2(at, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    require(space.valid() && a.valid() && H5Awrite(a, memory_type, value) >= 0, "attribute " + name);
  }
  std::string path_;
};

// The root's attributes: version, times, problem and case, fields; then /parameters and /terms.
void write_description(const Writer& w, hid_t file, const Problem& problem, const StepPlan& plan) {
  const ProblemDescription d = problem_description(problem);
  const std::vector<Field> fields = problem.fields();
  w.integer(file, "dlpverify_exchange_version", kExchangeVersion);
  w.text(file, "problem", d.problem);
  w.text(file, "case", problem.name());
  w.number(file, "t0", plan.t0);
  w.number(file, "dt", plan.dt);
  w.integer(file, "steps", plan.steps);
  w.number(file, "t_end", plan.t_end());
  w.integer(file, "members", problem.members());
  w.integer(file, "threads", plan.threads);
  std::vector<std::string> names, units;
  for (const Field& f : fields) names.push_back(f.name), units.push_back(f.unit);
  w.texts(file, "fields", names);
  w.texts(file, "field_units", units);

  Handle parameters(H5Gcreate2(file, "parameters", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  w.require(parameters.valid(), "group /parameters");
  for (const Parameter& p : d.parameters) {
    w.number(parameters, p.name, p.value);
    w.text(parameters, p.name + "_unit", p.unit);
  }
  Handle settings(H5Gcreate2(file, "terms", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  w.require(settings.valid(), "group /terms");
  for (const auto& [name, value] : d.settings) w.text(settings, name, value);
  if (d.member_data.empty()) return;
  Handle members(H5Gcreate2(file, "members", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  w.require(members.valid(), "group /members");
  for (const auto& [field, values] : d.member_data)
    w.column(members, field.name, values.data(), static_cast<hsize_t>(values.size()), field.unit);
}

}  // namespace

void write_exchange_file(const std::string& path, const Problem& problem, const State& state, const StepPlan& plan) {
  quiet_hdf5();
  const Writer w(path);
  const std::vector<Field> fields = problem.fields();
  w.require(state.rows() == problem.members() && state.cols() == static_cast<Eigen::Index>(fields.size()),
            "the state is not members x fields");
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  w.require(file.valid(), "cannot create it");
  write_description(w, file, problem, plan);
  Handle group(H5Gcreate2(file, "fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  w.require(group.valid(), "group /fields");
  const auto members = static_cast<hsize_t>(state.rows());
  for (std::size_t f = 0; f < fields.size(); ++f)
    w.column(group, fields[f].name, state.col(static_cast<Eigen::Index>(f)).data(), members, fields[f].unit);
  w.require(H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0, "flush");
}

namespace {

// The length of the one-dimensional dataset /fields/<name>, opened; ExchangeError when there is none.
hsize_t column_length(hid_t set, const std::string& where) {
  Handle space(H5Dget_space(set), H5Sclose);
  hsize_t length = 0;
  if (!space.valid() || H5Sget_simple_extent_ndims(space) != 1 || H5Sget_simple_extent_dims(space, &length, nullptr) != 1)
    throw ExchangeError(where + " is not one-dimensional");
  return length;
}

// One field's column from /fields/<name>: float64, one-dimensional, N long, every value finite.
// `any_number`: an integer or float of any size, converted by HDF5 (a member id).
void read_column(hid_t file, const Field& field, double* out, hsize_t members, bool any_number = false) {
  const std::string where = "/fields/" + field.name;
  if (H5Lexists(file, "fields", H5P_DEFAULT) <= 0) throw ExchangeError("it has no group /fields");
  if (H5Lexists(file, where.c_str(), H5P_DEFAULT) <= 0) throw ExchangeError("it has no field " + where);
  Handle set(H5Dopen2(file, where.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) throw ExchangeError(where + " is not a dataset");
  Handle type(H5Dget_type(set), H5Tclose);
  const bool float64 = type.valid() && H5Tget_class(type) == H5T_FLOAT && H5Tget_size(type) == 8;
  const bool number = type.valid() && (H5Tget_class(type) == H5T_FLOAT || H5Tget_class(type) == H5T_INTEGER);
  if (!(any_number ? number : float64)) throw ExchangeError(where + (any_number ? " is not a number" : " is not float64"));
  const hsize_t length = column_length(set, where);
  if (length != members)
    throw ExchangeError(where + " has length " + std::to_string(length) + ", expected " + std::to_string(members));
  if (H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) < 0)
    throw ExchangeError(where + " cannot be read (a damaged file?)");
  for (hsize_t p = 0; p < members; ++p)
    if (!std::isfinite(out[p]))
      throw ExchangeError(where + " has a non-finite value at member " + std::to_string(p) + " (" +
                          std::to_string(out[p]) + ")");
}

}  // namespace

namespace {

// The program's output opened as a regular file (io/input_file.hpp): a FIFO, device or folder a
// program left at `path` is refused without blocking; ExchangeError names the output.
int open_output(const std::string& path) {
  try {
    return open_input_file("output", path, input_limit::run);
  } catch (const InputError& e) {
    if (::access(path.c_str(), F_OK) != 0) throw ExchangeError("it wrote no output file " + path);
    throw ExchangeError("its output " + path + " " + e.reason());
  }
}

}  // namespace

void read_exchange_fields(const std::string& path, const Problem& problem, State& state) {
  quiet_hdf5();
  // HDF5 opens by name: it is given the checked descriptor's /proc/self/fd entry, the very file.
  const struct Checked {
    int fd;
    ~Checked() { ::close(fd); }
  } checked{open_output(path)};
  Handle file(H5Fopen(("/proc/self/fd/" + std::to_string(checked.fd)).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw ExchangeError("its output " + path + " is not an HDF5 file");
  const std::vector<Field> fields = problem.fields();
  const auto members = static_cast<hsize_t>(problem.members());
  state.resize(problem.members(), static_cast<Eigen::Index>(fields.size()));
  for (std::size_t f = 0; f < fields.size(); ++f)
    read_column(file, fields[f], state.col(static_cast<Eigen::Index>(f)).data(), members);
}

}  // namespace dlpverify::exchange

namespace dlpverify::exchange {

namespace {

// A numeric root attribute, when the file has one of that name.
template <class T>
std::optional<T> root_number(hid_t file, const char* name, hid_t memory_type) {
  if (H5Aexists(file, name) <= 0) return std::nullopt;
  Handle a(H5Aopen(file, name, H5P_DEFAULT), H5Aclose);
  Handle space(a.valid() ? H5Aget_space(a) : -1, H5Sclose);
  T value{};
  if (!space.valid() || H5Sget_simple_extent_npoints(space) != 1 || H5Aread(a, memory_type, &value) < 0)
    throw ExchangeError("its attribute " + std::string(name) + " is not one number");
  return value;
}

// A string attribute of `at` (one string or a list), read as variable-length UTF-8 strings.
std::vector<std::string> string_attribute(hid_t at, const char* name) {
  Handle a(H5Aopen(at, name, H5P_DEFAULT), H5Aclose);
  Handle stored(a.valid() ? H5Aget_type(a) : -1, H5Tclose);
  if (!stored.valid() || H5Tget_class(stored) != H5T_STRING || H5Tis_variable_str(stored) <= 0)
    throw ExchangeError("its attribute " + std::string(name) + " is not a variable-length string");
  Handle space(H5Aget_space(a), H5Sclose);
  const hssize_t count = space.valid() ? H5Sget_simple_extent_npoints(space) : -1;
  if (count < 0) throw ExchangeError("its attribute " + std::string(name) + " cannot be read");
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5Tget_cset(stored));
  std::vector<char*> pointers(static_cast<std::size_t>(count), nullptr);
  if (H5Aread(a, type, pointers.data()) < 0) throw ExchangeError("its attribute " + std::string(name) + " cannot be read");
  std::vector<std::string> values;
  for (char* p : pointers) values.emplace_back(p ? p : "");
  Handle scalar(H5Screate_simple(1, std::array<hsize_t, 1>{static_cast<hsize_t>(count)}.data(), nullptr), H5Sclose);
  H5Dvlen_reclaim(type, scalar, H5P_DEFAULT, pointers.data());
  return values;
}

// The names under /fields in HDF5's name order (the order when no `fields` attribute gives one).
std::vector<std::string> field_names(hid_t file) {
  if (H5Lexists(file, "fields", H5P_DEFAULT) <= 0) throw ExchangeError("it has no group /fields");
  if (H5Aexists(file, "fields") > 0) return string_attribute(file, "fields");
  Handle group(H5Gopen2(file, "fields", H5P_DEFAULT), H5Gclose);
  std::vector<std::string> names;
  const auto add = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  if (!group.valid() || H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, add, &names) < 0)
    throw ExchangeError("its group /fields cannot be listed");
  return names;
}

// A dataset's `unit` attribute, or "1" (no unit given).
std::string field_unit(hid_t file, const std::string& name) {
  Handle set(H5Dopen2(file, ("/fields/" + name).c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) throw ExchangeError("it has no field /fields/" + name);
  if (H5Aexists(set, "unit") <= 0) return "1";
  const std::vector<std::string> unit = string_attribute(set, "unit");
  return unit.size() == 1 ? unit.front() : "1";
}

}  // namespace

bool is_hdf5_file(const std::string& path) {
  quiet_hdf5();
  return H5Fis_hdf5(path.c_str()) > 0;
}

ExchangeRun read_exchange_run(const std::string& path) {
  quiet_hdf5();
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw ExchangeError("it is not an HDF5 file that can be read");
  ExchangeRun run;
  run.t0 = root_number<double>(file, "t0", H5T_NATIVE_DOUBLE);
  run.dt = root_number<double>(file, "dt", H5T_NATIVE_DOUBLE);
  run.t_end = root_number<double>(file, "t_end", H5T_NATIVE_DOUBLE);
  if (const auto steps = root_number<long long>(file, "steps", H5T_NATIVE_LLONG)) run.steps = static_cast<long>(*steps);

  std::vector<std::string> names = field_names(file);
  const auto id = std::find(names.begin(), names.end(), "id");
  const bool has_id = id != names.end() || H5Lexists(file, "/fields/id", H5P_DEFAULT) > 0;
  if (id != names.end()) names.erase(id);
  if (names.empty()) throw ExchangeError("it has no field under /fields");
  hsize_t members = 0;
  {
    Handle first(H5Dopen2(file, ("/fields/" + names.front()).c_str(), H5P_DEFAULT), H5Dclose);
    if (!first.valid()) throw ExchangeError("it has no field /fields/" + names.front());
    members = column_length(first, "/fields/" + names.front());
  }
  for (const std::string& name : names) run.fields.push_back({name, field_unit(file, name)});
  run.state.resize(static_cast<Eigen::Index>(members), static_cast<Eigen::Index>(names.size()));
  for (std::size_t f = 0; f < names.size(); ++f)
    read_column(file, run.fields[f], run.state.col(static_cast<Eigen::Index>(f)).data(), members);
  if (has_id) {
    run.ids = Eigen::ArrayXd(static_cast<Eigen::Index>(members));
    read_column(file, {"id", "1"}, run.ids->data(), members, true);
  }
  return run;
}

}  // namespace dlpverify::exchange
