#include "exchange/exchange_file.hpp"

#include "exchange/problem_description.hpp"

#include <algorithm>
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

// One field's column from /fields/<name>: float64, one-dimensional, N long, every value finite.
void read_column(hid_t file, const Field& field, double* out, hsize_t members) {
  const std::string where = "/fields/" + field.name;
  if (H5Lexists(file, "fields", H5P_DEFAULT) <= 0) throw ExchangeError("it has no group /fields");
  if (H5Lexists(file, where.c_str(), H5P_DEFAULT) <= 0) throw ExchangeError("it has no field " + where);
  Handle set(H5Dopen2(file, where.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) throw ExchangeError(where + " is not a dataset");
  Handle type(H5Dget_type(set), H5Tclose);
  if (!type.valid() || H5Tget_class(type) != H5T_FLOAT || H5Tget_size(type) != 8)
    throw ExchangeError(where + " is not float64");
  Handle space(H5Dget_space(set), H5Sclose);
  hsize_t length = 0;
  if (!space.valid() || H5Sget_simple_extent_ndims(space) != 1 || H5Sget_simple_extent_dims(space, &length, nullptr) != 1)
    throw ExchangeError(where + " is not one-dimensional");
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

void read_exchange_fields(const std::string& path, const Problem& problem, State& state) {
  quiet_hdf5();
  if (::access(path.c_str(), F_OK) != 0) throw ExchangeError("it wrote no output file " + path);
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw ExchangeError("its output " + path + " is not an HDF5 file");
  const std::vector<Field> fields = problem.fields();
  const auto members = static_cast<hsize_t>(problem.members());
  state.resize(problem.members(), static_cast<Eigen::Index>(fields.size()));
  for (std::size_t f = 0; f < fields.size(); ++f)
    read_column(file, fields[f], state.col(static_cast<Eigen::Index>(f)).data(), members);
}

}  // namespace dlpverify::exchange
