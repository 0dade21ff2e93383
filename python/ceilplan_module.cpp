// The `ceilplan` Python module: the library's maps, vehicles, routes and tours with numpy arrays
// for samples. docs/python.md walks through a session.

#include "ceilplan/ceilplan.hpp"
#include "ceilplan/io/geo_export.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <algorithm>

#include <cerrno>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace ceilplan;

namespace {

// The Python classes of an input file that cannot be read (set at import, used by the translator).
PyObject* input_file_error = nullptr;    // ceilplan.InputFileError: an InputError and an OSError
PyObject* missing_file_error = nullptr;  // ceilplan.MissingFileError: also a FileNotFoundError

// Raises an InputFileError as ceilplan.MissingFileError or ceilplan.InputFileError, its message
// the library's and its errno the reason's.
// NOLINTNEXTLINE(performance-unnecessary-value-param): pybind11's ExceptionTranslator takes it by value
void translateInputFileError(std::exception_ptr failure) {
  try {
    if (failure) std::rethrow_exception(failure);
  } catch (const InputFileError& e) {
    PyObject* type = e.reason() == std::errc::no_such_file_or_directory ? missing_file_error : input_file_error;
    py::object error = py::reinterpret_borrow<py::object>(type)(e.what());
    error.attr("errno") = static_cast<int>(e.reason());
    PyErr_SetObject(type, error.ptr());
  }
}

// numpy at import, where a missing numpy can be named, and before any thread can race for it:
// pybind11 looks numpy's API up once, in a function-local static that imports numpy. Looked up
// for the first time by two threads, one holds the static's guard and waits for the GIL while
// the other holds the GIL and waits for the guard.
void loadNumpy() {
  try {
    py::module_::import("numpy");
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ImportError)) throw;
    throw py::import_error(std::string("ceilplan needs numpy for this interpreter (") + PY_VERSION + ", " +
                           py::str(py::module_::import("sys").attr("executable")).cast<std::string>() +
                           "): install python3-numpy (Debian) or 'pip install numpy'; " + e.what());
  }
  py::detail::npy_api::get();
}

// A map indexed for a vehicle and a battery: what plans and evaluations run against.
struct PyEnvironment {
  std::shared_ptr<const mission::PlanningContext> context;
};

struct PyMission {
  mission::Mission mission;
};

// A planned tour, with what writing its files needs.
struct PyTour {
  mission::TourResult tour;
  std::shared_ptr<const mission::Mission> mission;
  std::shared_ptr<const mission::PlanningContext> context;
  std::string call;  // how it was planned, for the provenance of what Tour.write writes
};

// `plan_tour(mode="both")`: both modes over one indexed map, as `ceilplan tour --mode both`.
struct PyTourComparison {
  std::shared_ptr<PyTour> ceiling, free;
  std::string call;
};

// A Python callable `progress(stage, fraction)` as the library's progress callback. The work runs
// without the GIL; each report takes it, runs pending signal handlers (Ctrl-C) and calls the
// callable. An exception either raises cancels the work: the library unwinds on Cancelled (no
// std::exception, so nothing on the way takes it for a library error) and run() raises the Python
// exception. The state outlives the call (a PlanningContext keeps its callback) but reports
// nothing once run() has returned.
class PythonProgress {
 public:
  explicit PythonProgress(const py::object& callable) : state_(std::make_shared<State>()) {
    if (!callable.is_none() && !PyCallable_Check(callable.ptr()))
      throw InputError("progress must be a callable progress(stage, fraction), or None");
    state_->callable = callable.is_none() ? nullptr : callable.ptr();  // borrowed: the caller holds it
  }

  ProgressCallback callback() const {
    return [state = state_](const std::string& stage, double fraction) { report(*state, stage, fraction); };
  }

  // Runs `work` without the GIL; raises what the callable raised, if it did.
  template <class Work>
  auto run(Work&& work) -> decltype(work()) {
    try {
      py::gil_scoped_release release;
      auto result = work();
      state_->active = false;
      return result;
    } catch (...) {
      state_->active = false;
      if (state_->raised) throw py::error_already_set(*state_->raised);
      throw;
    }
  }

 private:
  struct Cancelled {};
  struct State {
    PyObject* callable = nullptr;
    bool active = true;
    std::optional<py::error_already_set> raised;
  };

  static void report(State& state, const std::string& stage, double fraction) {
    if (!state.active) return;
    if (state.raised) throw Cancelled{};
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (state.callable) py::handle(state.callable)(stage, fraction);
    } catch (py::error_already_set& e) {
      state.raised = e;
      throw Cancelled{};
    }
  }

  std::shared_ptr<State> state_;
};

// "a, b or c", for docstrings that list the values an argument takes.
std::string oneOf(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + ("'" + names[k] + "'");
  return text;
}

// The shipped cameras' names, for docstrings.
std::string cameraPresetNames() {
  std::vector<std::string> names;
  for (const mission::CameraPreset& preset : mission::cameraPresets()) names.push_back(preset.camera.name);
  return oneOf(names);
}

// Results are dicts (indexing, ==, and whatever takes a dict take them as before) of a named subclass
// whose repr is one short line, with the units in its names.
using ResultSummary = std::string (*)(const py::dict&);

void addResultType(py::module_& m, const char* name, const std::string& doc, ResultSummary summary) {
  py::dict attributes;
  attributes["__doc__"] = doc;
  attributes["__module__"] = "ceilplan";
  attributes["__slots__"] = py::tuple();
  const py::cpp_function repr(
      [name, summary](const py::dict& self) { return std::string(name) + "(" + summary(self) + ")"; },
      py::name("__repr__"), "A one-line summary; the keys hold the whole result");
  attributes["__repr__"] = py::reinterpret_steal<py::object>(PyInstanceMethod_New(repr.ptr()));
  const auto type = py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(&PyType_Type));
  const auto dict = py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(&PyDict_Type));
  m.attr(name) = type(name, py::make_tuple(dict), attributes);
}

py::object result(const char* type, const py::dict& fields) {
  return py::module_::import("ceilplan").attr(type)(fields);
}

// The names of a mission's targets, surfaces or contact grids.
template <class Named>
std::vector<std::string> namesOf(const std::vector<Named>& items) {
  std::vector<std::string> names;
  names.reserve(items.size());
  for (const Named& item : items) names.push_back(item.name);
  return names;
}

// A figure of a result for its repr: "charge_ah=0.7010", "None" where it has none.
std::string figure(const py::dict& d, const char* key, int decimals) {
  const py::object value = d[key];
  return std::string(key) + "=" + (value.is_none() ? std::string("None") : formatFixed(value.cast<double>(), decimals));
}

std::string count(const py::dict& d, const char* key) {
  return std::string(key) + "=" + std::to_string(py::len(d[key]));
}

std::string quoted(const py::handle& value) { return py::repr(value).cast<std::string>(); }

double noneAsInfinity(const std::optional<double>& value) { return value ? *value : energy::kNoSurface; }
py::object infinityAsNone(double value) { return std::isfinite(value) ? py::object(py::float_(value)) : py::none(); }

Eigen::Vector3d point(const std::vector<double>& xyz, const char* what) {
  if (xyz.size() != 3) throw InputError(std::string(what) + " must be (x, y, z) in metres");
  return {xyz[0], xyz[1], xyz[2]};
}

// A crop box given as (xmin, ymin, zmin, xmax, ymax, zmax); its corners are checked where it is used.
Eigen::AlignedBox3d cropBox(const std::vector<double>& corners) {
  if (corners.size() != 6) throw InputError("crop must be (xmin, ymin, zmin, xmax, ymax, zmax) in metres");
  return {Eigen::Vector3d(corners[0], corners[1], corners[2]), Eigen::Vector3d(corners[3], corners[4], corners[5])};
}

environment::UnknownSpace unknownSpace(const std::string& policy, std::optional<double> fill_max_m) {
  return environment::parseUnknownSpace(policy, fill_max_m, {"unknown", "unknown_fill_max_m"});
}

// A mission's `wind:` as Python sees it: a dict with the file's keys.
py::dict windDict(const energy::Wind& wind) {
  py::dict d;
  d["speed_m_s"] = wind.speed_m_s;
  d["from_deg"] = wind.from_deg;
  d["gust_m_s"] = wind.gust_m_s;
  d["sheltered_fraction"] = wind.sheltered_fraction;
  return d;
}

// The same dict back, strict as the file's key: speed_m_s and from_deg required, no other key.
energy::Wind windOf(const py::dict& d) {
  energy::Wind wind;
  const std::vector<std::string> keys{"speed_m_s", "from_deg", "gust_m_s", "sheltered_fraction"};
  for (const auto& [key, value] : d) {
    const std::string name = py::str(key);
    if (std::find(keys.begin(), keys.end(), name) == keys.end())
      throw InputError("wind: unknown key '" + name + "' (keys: speed_m_s, from_deg, gust_m_s, sheltered_fraction)");
  }
  for (const char* required : {"speed_m_s", "from_deg"})
    if (!d.contains(required)) throw InputError(std::string("wind: missing key '") + required + "'");
  wind.speed_m_s = d["speed_m_s"].cast<double>();
  wind.from_deg = d["from_deg"].cast<double>();
  if (d.contains("gust_m_s")) wind.gust_m_s = d["gust_m_s"].cast<double>();
  if (d.contains("sheltered_fraction")) wind.sheltered_fraction = d["sheltered_fraction"].cast<double>();
  wind.validate();
  return wind;
}

py::dict gapsDict(const environment::SurfaceGaps& gaps) {
  py::dict d;
  d["nearest_gap_m"] = infinityAsNone(gaps.nearest_gap_m);
  d["coverage"] = gaps.coverage;
  d["mean_gap_m"] = infinityAsNone(gaps.mean_gap_m);
  return d;
}

// path.csv's columns as numpy arrays, one entry per row: a tour's (with sortie and phase) or a
// route's (`ceilplan plan`), same names and values; a missing gap is NaN as the empty field is.
py::object sampleColumns(const std::vector<io::TourPathRow>& rows, bool tour) {
  const std::size_t n = rows.size();
  py::array_t<double> t(n), x(n), y(n), z(n), speed(n), gap(n), current(n), soc(n), ground(n);
  py::array_t<int> sortie(n);
  py::array_t<bool> assumed_free(n);
  py::list phase;
  const auto nanIfNone = [](double gap_m) { return std::isfinite(gap_m) ? gap_m : std::nan(""); };
  for (std::size_t k = 0; k < n; ++k) {
    const io::TourPathRow& row = rows[k];
    t.mutable_at(k) = row.t_s;
    x.mutable_at(k) = row.position_m.x();
    y.mutable_at(k) = row.position_m.y();
    z.mutable_at(k) = row.position_m.z();
    speed.mutable_at(k) = row.speed_m_s;
    gap.mutable_at(k) = nanIfNone(row.ceiling_gap_m);
    current.mutable_at(k) = row.current_a;
    soc.mutable_at(k) = row.soc;
    sortie.mutable_at(k) = row.sortie;
    ground.mutable_at(k) = nanIfNone(row.ground_gap_m);
    assumed_free.mutable_at(k) = row.assumed_free;
    if (tour) phase.append(row.phase);
  }
  py::dict d;
  d["t_s"] = t;
  d["x"] = x;
  d["y"] = y;
  d["z"] = z;
  d["speed_m_s"] = speed;
  d["ceiling_gap_m"] = gap;
  d["current_a"] = current;
  d["soc"] = soc;
  if (tour) d["sortie"] = sortie;
  d["ground_gap_m"] = ground;
  if (tour) d["phase"] = py::module_::import("numpy").attr("array")(phase, py::arg("dtype") = "U8");
  d["assumed_free"] = assumed_free;
  return result("Samples", d);
}

py::object routeSamples(const std::vector<planner::PathSample>& samples) {
  std::vector<io::TourPathRow> rows;
  rows.reserve(samples.size());
  for (const planner::PathSample& s : samples)
    rows.push_back({s.t_s, s.position_m, s.speed_m_s, s.ceiling_gap_m, s.current_a, s.soc, 1, s.ground_gap_m, "leg",
                    s.assumed_free});
  return sampleColumns(rows, false);
}

py::dict evaluationDict(const planner::PathEvaluation& e) {
  py::dict d;
  d["length_m"] = e.length_m;
  d["duration_s"] = e.duration_s;
  d["charge_ah"] = e.charge_ah;
  d["energy_wh"] = e.energy_wh;
  d["fec"] = e.fec;
  d["mean_current_a"] = e.mean_current_a;
  d["min_soc"] = e.min_soc;
  d["min_clearance_m"] = infinityAsNone(e.min_clearance_m);
  d["min_ceiling_gap_m"] = infinityAsNone(e.min_ceiling_gap_m);
  d["time_under_ceiling_s"] = e.time_under_ceiling_s;
  d["samples"] = routeSamples(e.samples);
  return d;
}

// The photos of a coverage tour as flown (photos.csv's columns) as numpy arrays, regions as a list.
py::object photoArrays(const std::vector<mission::PhotoRow>& rows) {
  const std::size_t n = rows.size();
  py::array_t<int> index(n), sortie(n);
  py::array_t<double> t(n), x(n), y(n), z(n), yaw(n), pitch(n), distance(n), gsd(n);
  std::vector<std::string> regions;
  for (std::size_t k = 0; k < n; ++k) {
    const mission::PhotoRow& row = rows[k];
    index.mutable_at(k) = row.index;
    sortie.mutable_at(k) = row.sortie.value_or(0);
    t.mutable_at(k) = row.t_s.value_or(std::nan(""));
    x.mutable_at(k) = row.camera_m.x();
    y.mutable_at(k) = row.camera_m.y();
    z.mutable_at(k) = row.camera_m.z();
    yaw.mutable_at(k) = row.yaw_deg;
    pitch.mutable_at(k) = row.gimbal_pitch_deg;
    distance.mutable_at(k) = row.distance_m;
    gsd.mutable_at(k) = row.gsd_mm_px;
    regions.push_back(row.region);
  }
  py::dict d;
  d["index"] = index;
  d["sortie"] = sortie;
  d["t_s"] = t;
  d["x"] = x;
  d["y"] = y;
  d["z"] = z;
  d["yaw_deg"] = yaw;
  d["gimbal_pitch_deg"] = pitch;
  d["distance_m"] = distance;
  d["gsd_mm_px"] = gsd;
  d["region"] = regions;
  return result("Photos", d);
}

// A JSON document as Python objects.
py::object pythonJson(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(io::jsonText(json));
}

py::object noneIfEmpty(const std::optional<double>& value) {
  return value ? py::object(py::float_(*value)) : py::none();
}

// A duty-series of samples as numpy arrays: t_s, current_a, soc, fec.
py::dict dutySeries(const std::vector<battery::Sample>& samples) {
  py::array_t<double> t(samples.size()), current(samples.size()), soc(samples.size()), fec(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    t.mutable_at(k) = samples[k].t_s;
    current.mutable_at(k) = samples[k].current_a;
    soc.mutable_at(k) = samples[k].soc;
    fec.mutable_at(k) = samples[k].fec_continuous;
  }
  py::dict d;
  d["t_s"] = t;
  d["current_a"] = current;
  d["soc"] = soc;
  d["fec"] = fec;
  return d;
}

py::dict dutyAgeingDict(const battery::DutyStudyAgeing& ageing) {
  const battery::LifetimeResult& p = ageing.projection;
  py::dict d;
  d["cycle_wear_name"] = p.cycle_wear_name;
  d["cycle_wear"] = p.cycle_wear;
  d["cycle_wear_new_pack"] = ageing.new_pack.cycle_wear;
  d["capacity_fade"] = p.capacity_loss;
  d["fec"] = p.fec;
  d["faded_pack_cycles"] = p.faded_pack_cycles;
  d["min_soc"] = p.min_soc;
  d["days_flown"] = p.days_flown;
  d["days_to_end_of_life"] = noneIfEmpty(p.days_to_end_of_life);
  d["missions_to_end_of_life"] =
      p.missions_to_end_of_life ? py::object(py::int_(*p.missions_to_end_of_life)) : py::none();
  d["wear_reduction_pct"] = noneIfEmpty(ageing.wear_reduction_pct);
  d["wear_reduction_new_pack_pct"] = noneIfEmpty(ageing.wear_reduction_new_pack_pct);
  d["fade_reduction_pct"] = noneIfEmpty(ageing.fade_reduction_pct);
  d["soh_by_day"] = py::array_t<double>(p.soh_by_day.size(), p.soh_by_day.data());
  d["stopped_because"] = p.stopped_because;
  d["warnings"] = p.warnings;
  return d;
}

py::object dutyStudyResult(const battery::DutyStudyOptions& options, const battery::DutyStudyResult& study) {
  py::list cases;
  for (const battery::DutyStudyCase& c : study.cases) {
    py::dict d;
    d["flight_current_a"] = c.flight_current_a;
    d["min_soc"] = c.run.minSoc();
    d["max_dod"] = c.max_dod;
    d["charge_end_s"] = c.run.missions.back().charge_end_s;
    d["fec"] = c.run.fecTotal();
    d["fec_per_mission"] = c.run.fecPerMission();
    d["fec_per_day"] = c.run.fecPerDay();
    d["charge_ah"] = c.run.final_state.charge_ah;
    d["discharge_ah"] = c.run.final_state.discharge_ah;
    d["fec_reduction_pct"] = c.fec_reduction_pct;
    py::dict ageing;
    for (std::size_t m = 0; m < c.ageing.size(); ++m)
      ageing[py::str(options.ageing_models[m])] = dutyAgeingDict(c.ageing[m]);
    d["ageing"] = ageing;
    d["first_day"] = dutySeries(c.run.first_day);
    cases.append(result("DutyCase", d));
  }
  py::dict comparison_days;
  for (std::size_t m = 0; m < study.comparison_days.size(); ++m)
    comparison_days[py::str(options.ageing_models[m])] = study.comparison_days[m];
  py::dict d;
  d["study_days"] = study.study_days;
  d["span"] = options.spanText();
  d["cases"] = cases;
  d["comparison_days"] = comparison_days;
  d["table"] = io::dutyStudyTable(options, study);
  return result("DutyStudy", d);
}

// The tour's sorties as tour.json gives them, each with its number, home and waypoints as the
// autopilot files and routes.geojson fly them (map frame), its legs as Leg results.
py::list sortieList(const mission::TourResult& tour) {
  const py::list sorties = pythonJson(io::tourSortiesJson(tour));
  py::list list;
  for (std::size_t k = 0; k < sorties.size(); ++k) {
    const mission::SortieRoute& route = tour.routes[k];
    py::dict d;
    d["sortie"] = k + 1;
    for (const auto item : sorties[k].cast<py::dict>()) d[item.first] = item.second;
    py::list legs;
    for (const py::handle leg : d["legs"]) legs.append(result("Leg", leg.cast<py::dict>()));
    d["legs"] = legs;
    d["home"] = std::vector<double>{route.home_m.x(), route.home_m.y(), route.home_m.z()};
    d["waypoints"] = pythonJson(io::routeWaypointsJson(route));
    list.append(result("Sortie", d));
  }
  return list;
}

// What Tour.write and TourComparison.write write, by the rules of `ceilplan tour --out`: replaced
// whole, only if ceilplan wrote it (or it is empty); both modes in DIR/ceiling and DIR/free with
// the comparison beside them.
void writeTours(const std::filesystem::path& dir, const std::vector<const PyTour*>& tours, bool export_autopilot,
                const std::string& call) {
  const PyTour& first = *tours.front();
  std::optional<io::Autopilot> autopilot;
  if (export_autopilot) autopilot = io::Autopilot::PX4;
  const std::string written =
      "python: " + call + ".write('" + dir.string() + "', autopilot=" + (export_autopilot ? "True" : "False") + ")";
  const io::Provenance provenance =
      io::tourProvenance(io::Provenance::of(written), *first.mission, first.tour.planning.seed);
  io::OutputSet out({{"dir", dir, true}}, {{"the mission's map", first.mission->map_file},
                                           {"the mission's vehicle", first.mission->vehicle_file}});
  const environment::Environment& environment = first.context->environment();
  for (const PyTour* tour : tours) {
    const std::filesystem::path mode_dir =
        tours.size() > 1 ? out.path() / mission::flightModeName(tour->tour.mode) : out.path();
    io::writeTourDirectory(mode_dir, tour->tour, *first.mission, environment, autopilot, provenance);
  }
  if (tours.size() == 2)
    io::writeTourComparison(out.path(), tours[0]->tour, tours[1]->tour, *first.mission, environment, provenance);
  out.commit();
}

// The one-line summaries of the results' reprs.
std::string routeSummary(const py::dict& d) {
  return "planner=" + quoted(d["planner"]) + ", " + count(d, "waypoints") + ", " + figure(d, "length_m", 2) + ", " +
         figure(d, "duration_s", 1) + ", " + figure(d, "charge_ah", 4) + ", " + figure(d, "min_soc", 3);
}

std::string evaluationSummary(const py::dict& d) {
  return "valid=" + quoted(d["valid"]) + ", " + figure(d, "length_m", 2) + ", " + figure(d, "duration_s", 1) + ", " +
         figure(d, "charge_ah", 4) + ", " + figure(d, "min_clearance_m", 3);
}

std::string samplesSummary(const py::dict& d) {
  const auto t = d["t_s"].cast<py::array_t<double>>();
  std::string columns;
  for (const auto item : d) columns += (columns.empty() ? "" : ", ") + item.first.cast<std::string>();
  const std::string span =
      t.size() == 0 ? "" : ", t_s=" + formatFixed(t.at(0), 1) + "-" + formatFixed(t.at(t.size() - 1), 1);
  return "rows=" + std::to_string(t.size()) + span + ", columns: " + columns;
}

std::string sortieSummary(const py::dict& d) {
  return "sortie=" + quoted(d["sortie"]) + ", " + count(d, "targets") + ", " + count(d, "legs") + ", " +
         count(d, "waypoints") + ", " + figure(d, "charge_ah", 4) + ", " + figure(d, "duration_s", 1) + ", " +
         figure(d, "min_soc", 3);
}

std::string legSummary(const py::dict& d) {
  return quoted(d["from"]) + " -> " + quoted(d["to"]) + ", " + figure(d, "length_m", 2) + ", " +
         figure(d, "duration_s", 1) + ", " + figure(d, "charge_ah", 4) + ", " + count(d, "waypoints");
}

std::string probeSummary(const py::dict& d) {
  const auto gap = [](const py::dict& gaps) {
    const py::object nearest = gaps["nearest_gap_m"];
    return nearest.is_none() ? std::string("None") : formatFixed(nearest.cast<double>(), 3);
  };
  return "valid=" + quoted(d["valid"]) + ", " + figure(d, "clearance_m", 3) +
         ", ceiling_gap_m=" + gap(d["ceiling"].cast<py::dict>()) +
         ", ground_gap_m=" + gap(d["ground"].cast<py::dict>());
}

std::string photosSummary(const py::dict& d) {
  py::list regions;
  for (const py::handle region : d["region"])
    if (!regions.contains(region)) regions.append(region);
  return "photos=" + std::to_string(py::len(d["index"])) + ", regions=" + quoted(regions);
}

std::string coverageSummary(const py::dict& d) {
  std::string regions;
  for (const py::handle region : d["regions"])
    regions +=
        ", " + region["name"].cast<std::string>() + " " + figure(region.cast<py::dict>(), "covered_reachable_pct", 1);
  return "photos=" + quoted(d["photos"]) + regions;
}

std::string dutyStudySummary(const py::dict& d) {
  std::string cases;
  for (const py::handle c : d["cases"])
    cases += ", " + formatNumber(c["flight_current_a"].cast<double>()) + " A: " + figure(c.cast<py::dict>(), "fec", 2);
  return "study_days=" + quoted(d["study_days"]) + cases;
}

std::string dutyCaseSummary(const py::dict& d) {
  return figure(d, "flight_current_a", 2) + ", " + figure(d, "min_soc", 3) + ", " + figure(d, "fec", 2) + ", " +
         figure(d, "fec_reduction_pct", 2);
}

std::string mapImportSummary(const py::dict& d) {
  return "map=" + quoted(d["map"]) + ", kind=" + quoted(d["kind"]) + ", " + figure(d, "resolution_m", 3);
}

std::string proposalSummary(const py::dict& d) {
  return count(d, "regions") + ", " + figure(d, "overhead_area_m2", 1) + ", home=" + quoted(d["home"]) +
         ", mission=" + quoted(py::str(d["mission"]));
}

}  // namespace

PYBIND11_MODULE(ceilplan, m) {
  m.doc() =
      "ceilplan: battery-wear-aware inspection planning for multirotors flying under ceilings (docs/python.md). "
      "SI units throughout, in the names: _m metres, _s seconds, _a amperes, _ah ampere-hours; SOC in [0, 1]";
  m.attr("__version__") = kVersion;
  loadNumpy();

  // The library's error hierarchy; pybind11 tries translators newest first, so the base goes first.
  // InputError is also a ValueError, as Python code expects of bad arguments.
  const auto& error = py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  const auto& infeasible = py::register_exception<InfeasibleError>(m, "InfeasibleError", error);
  py::register_exception<NoPathError>(m, "NoPathError", infeasible);
  const auto& input =
      py::register_exception<InputError>(m, "InputError", py::make_tuple(error, py::handle(PyExc_ValueError)));
  // An input file that cannot be read is also an OSError (a missing one a FileNotFoundError), as
  // Python's own open() raises. Registered last, so tried before InputError's translator.
  const py::tuple file_bases = py::make_tuple(input, py::handle(PyExc_OSError));
  input_file_error = PyErr_NewException("ceilplan.InputFileError", file_bases.ptr(), nullptr);
  const py::tuple missing_bases = py::make_tuple(py::handle(input_file_error), py::handle(PyExc_FileNotFoundError));
  missing_file_error = PyErr_NewException("ceilplan.MissingFileError", missing_bases.ptr(), nullptr);
  if (!input_file_error || !missing_file_error) throw py::error_already_set();
  m.attr("InputFileError") = py::handle(input_file_error);
  m.attr("MissingFileError") = py::handle(missing_file_error);
  py::register_exception_translator(translateInputFileError);
  m.attr("Error").attr("__doc__") =
      "A computation of the library failed (a RuntimeError); the base of every ceilplan error";
  m.attr("InfeasibleError").attr("__doc__") = "A well-formed request that cannot be met (a target no sortie reaches)";
  m.attr("NoPathError").attr("__doc__") = "No path exists between two places (an InfeasibleError)";
  m.attr("InputError").attr("__doc__") = "Bad input: an argument, a file or a key (also a ValueError); says what to do";
  m.attr("InputFileError").attr("__doc__") =
      "An input file that cannot be read (an InputError and an OSError with its errno: EISDIR, EINVAL, ...)";
  m.attr("MissingFileError").attr("__doc__") = "An input file that does not exist (also a FileNotFoundError)";

  // The result types: dicts with a short repr (docs/python.md, "Results").
  addResultType(m, "Route",
                "plan()'s route (a dict): waypoints [(x, y, z) m], cost and cost_unit, planner, seed, and the figures "
                "of evaluate(): length_m, duration_s, charge_ah, energy_wh, fec, mean_current_a, min_soc, "
                "min_clearance_m, min_ceiling_gap_m (None: no ceiling), time_under_ceiling_s, samples (Samples)",
                routeSummary);
  addResultType(m, "Evaluation",
                "evaluate()'s figures of a path (a dict): valid, violation (None or why not), cost, length_m, "
                "duration_s, charge_ah, energy_wh, fec, mean_current_a, min_soc, min_clearance_m, min_ceiling_gap_m "
                "(None: no ceiling), time_under_ceiling_s, samples (Samples)",
                evaluationSummary);
  addResultType(m, "Samples",
                "Flown samples as numpy arrays of one length (a dict), path.csv's columns by path.csv's names: t_s, "
                "x, y, z (m), speed_m_s, ceiling_gap_m and ground_gap_m (from the rotor plane; NaN: no surface), "
                "current_a, soc, assumed_free (bool: the point relies on the unknown-space policy); a tour's add "
                "sortie (1-based) and phase ('leg', 'dwell' or 'recharge': the pack back at the start SOC after a "
                "sortie, on its own clock, its current the mean charge current, negative)",
                samplesSummary);
  addResultType(m, "Sortie",
                "One sortie of a Tour (a dict), as tour.json gives it: sortie (1-based), targets (names in visiting "
                "order), legs (Leg), home [x, y, z] m, waypoints (as the autopilot files fly them, map frame: name, "
                "map_m [x, y, z], hold_s, yaw_deg (heading in effect, clockwise from north), speed_m_s (towards the "
                "next), gimbal_pitch_deg (+90 straight up, None: unchanged), take_photo, contact_reading, "
                "height_above_home_m, index, sortie, kind), takeoff_height_m, landing_height_m (None: does not end "
                "at home), takeoff_s (on the tour's clock), charge_ah, duration_s (take-off to landing), recharge_s, "
                "turnaround_s, fec, dod, min_soc (at landing), wear (the split's ageing model), reason; with a "
                "calibrated vehicle also p_land_above_reserve, soc_p01 (1st-percentile landing SOC), "
                "landing_soc_std and sampled_landing (docs/tours.md, \"Landing confidence\")",
                sortieSummary);
  addResultType(m, "Leg",
                "One leg of a Sortie (a dict): from, to (place names), charge_ah, duration_s, length_m, waypoints "
                "[[x, y, z] m]",
                legSummary);
  addResultType(m, "Probe",
                "Environment.probe()'s answer (a dict): ceiling and ground ({nearest_gap_m, coverage, mean_gap_m}; "
                "None: no surface), clearance_m, valid, violation (None or why not)",
                probeSummary);
  addResultType(m, "Photos",
                "A coverage tour's photos as flown (a dict), photos.csv's columns: index, sortie, t_s, x, y, z "
                "(camera, m), yaw_deg, gimbal_pitch_deg, distance_m, gsd_mm_px as numpy arrays, region a list",
                photosSummary);
  addResultType(m, "Coverage",
                "A coverage tour's coverage.json (a dict): regions (area_m2, covered_area_m2, covered_pct, "
                "covered_reachable_pct, unreachable_area_m2, mean_gsd_mm_px, gsd_histogram, photos, passes, "
                "uncovered_centres, ...), photos, check",
                coverageSummary);
  addResultType(m, "DutyStudy",
                "duty()'s study (a dict): study_days, span, cases (DutyCase), comparison_days per ageing model, "
                "table (the text `ceilplan duty` prints)",
                dutyStudySummary);
  addResultType(m, "DutyCase",
                "One flight current of a DutyStudy (a dict): flight_current_a, min_soc, max_dod, charge_end_s, fec, "
                "fec_per_mission, fec_per_day, charge_ah, discharge_ah, fec_reduction_pct, ageing (per model), "
                "first_day (t_s, current_a, soc, fec arrays)",
                dutyCaseSummary);
  addResultType(m, "MapImport",
                "import_map()'s summary (a dict, <out>.json): map, source, kind ('points' or 'mesh'), origins, "
                "resolution_m, free_space (what was assumed), crop_m, extent_m, figures, crs, provenance",
                mapImportSummary);
  addResultType(m, "Proposal",
                "propose()'s mission (a dict): regions (name, box_min, box_max [m], area_m2, elements), home [x, y, z] "
                "m, home_given, home_height_m, dropped_regions, dropped_area_m2, overhead_area_m2, too_low_area_m2, "
                "min_room_below_m, mission and picture (the files written)",
                proposalSummary);

  py::class_<mission::Vehicle>(m, "Vehicle", "A multirotor: its shape and its energy model (docs/energy.md)")
      .def_static("default", &mission::Vehicle::defaultQuad, "The built-in quadrotor (maps/vehicles/quad.yaml)")
      .def_static(
          "load", [](const std::filesystem::path& file) { return io::readVehicle(file); },
          "Reads a vehicle file (docs/energy.md); raises InputError naming the bad key", py::arg("path"))
      .def_readonly("name", &mission::Vehicle::name, "The vehicle's name (str)")
      .def("__repr__",
           [](const mission::Vehicle& vehicle) { return "Vehicle(name=" + quoted(py::str(vehicle.name)) + ")"; })
      .def(
          "current_a",
          [](const mission::Vehicle& vehicle, std::optional<double> ceiling_gap_m, double coverage,
             std::optional<double> ground_gap_m, double speed_m_s, double climb_m_s, std::optional<double> soc) {
            const energy::EnergyModel model(vehicle.energy);
            energy::FlightCondition flight;
            flight.ground_gap_m = noneAsInfinity(ground_gap_m);
            flight.speed_m_s = speed_m_s;
            flight.climb_m_s = climb_m_s;
            flight.soc = soc.value_or(vehicle.energy.reference_soc);
            return model.currentA(noneAsInfinity(ceiling_gap_m), coverage, flight);
          },
          "Pack current (A) in one flight condition: ceiling_gap_m and ground_gap_m from the rotor plane (m; None: no "
          "surface), coverage (share of each rotor disc under the ceiling, 0 to 1), speed_m_s, climb_m_s, soc (0 to "
          "1; None: the vehicle's reference SOC)",
          py::arg("ceiling_gap_m") = py::none(), py::arg("coverage") = 1.0, py::arg("ground_gap_m") = py::none(),
          py::arg("speed_m_s") = 0.0, py::arg("climb_m_s") = 0.0, py::arg("soc") = py::none());

  py::class_<PyEnvironment>(m, "Environment", "A map indexed for a vehicle and a battery")
      .def_static(
          "load",
          [](const std::filesystem::path& path, const std::optional<mission::Vehicle>& vehicle,
             const std::optional<std::filesystem::path>& battery, const std::string& unknown,
             std::optional<double> unknown_fill_max_m, const py::object& progress) {
            mission::PlanningOptions options;
            options.unknown = unknownSpace(unknown, unknown_fill_max_m);
            const mission::Vehicle flown = vehicle.value_or(mission::Vehicle::defaultQuad());
            const mission::BatterySpec pack = io::readBatteryOrDefault(battery.value_or(""), flown);
            PythonProgress reporter(progress);
            return reporter.run([&] {  // loading and indexing a map takes seconds
              return PyEnvironment{std::make_shared<mission::PlanningContext>(
                  environment::OccupancyMap::load(path), flown, pack, options, reporter.callback())};
            });
          },
          "Loads an OctoMap (.bt or .ot) and indexes it for `vehicle` (None: the built-in one) and a battery file "
          "(None: the founding paper's 5.2 Ah pack from 95 %). unknown: what the map's unknown voxels count as, "
          "'occupied' (the default), 'free' or 'fill' (unknown_fill_max_m: the largest unknown pocket filled, m, "
          "with 'fill' only). progress: None or a callable progress(stage, fraction) (see plan_tour)",
          py::arg("path"), py::arg("vehicle") = py::none(), py::arg("battery") = py::none(),
          py::arg("unknown") = "occupied", py::arg("unknown_fill_max_m") = py::none(), py::arg("progress") = py::none())
      .def(
          "probe",
          [](const PyEnvironment& self, double x, double y, double z) {
            const environment::PositionProbe probe =
                environment::probePosition(self.context->environment(), Eigen::Vector3d(x, y, z));
            py::dict d;
            d["ceiling"] = gapsDict(probe.ceiling);
            d["ground"] = gapsDict(probe.ground);
            d["clearance_m"] = infinityAsNone(probe.clearance_m);
            d["valid"] = !probe.violation;
            d["violation"] = probe.violation ? py::object(py::str(probe.violation->describe())) : py::none();
            return result("Probe", d);
          },
          "A Probe: gaps above and below the rotors, clearance and validity with the body centre at (x, y, z) m, as "
          "`ceilplan probe`",
          py::arg("x"), py::arg("y"), py::arg("z"))
      .def_property_readonly(
          "resolution_m", [](const PyEnvironment& self) { return self.context->map().resolution_m(); },
          "The map's voxel size (m)")
      .def("__repr__", [](const PyEnvironment& self) {
        return "Environment(resolution_m=" + formatNumber(self.context->map().resolution_m()) +
               ", vehicle=" + quoted(py::str(self.context->vehicle().name)) +
               ", unknown=" + quoted(py::str(self.context->environment().unknownSpace().describe())) + ")";
      });

  const planner::PlanRequest defaults;  // `ceilplan plan`'s defaults too
  m.def(
      "plan",
      [](const PyEnvironment& env, const std::vector<double>& start, const std::vector<double>& goal,
         const std::string& mode, const std::string& objective, const std::string& planner, double time_limit_s,
         std::uint32_t seed, double lattice_spacing_m, double band_fraction, bool refine) {
        planner::seedOmpl(seed);  // only the first seed of a process takes effect (OMPL's generators)
        planner::PlanRequest request;
        request.start_m = point(start, "start");
        request.goal_m = point(goal, "goal");
        request.planner = planner;
        request.time_limit_s = time_limit_s;
        request.lattice.spacing_m = lattice_spacing_m;
        request.band_fraction = band_fraction;
        request.refine = refine;
        const mission::FlightMode flight_mode = mission::flightModeFromName(mode);
        const mission::RoutePlan route = [&] {
          py::gil_scoped_release release;
          return mission::planRoute(*env.context, flight_mode, request, objective);
        }();
        py::dict d = evaluationDict(route.evaluation);
        std::vector<std::vector<double>> waypoints;
        for (const Eigen::Vector3d& p : route.plan.waypoints) waypoints.push_back({p.x(), p.y(), p.z()});
        d["waypoints"] = waypoints;
        d["cost"] = route.plan.cost;
        d["cost_unit"] = route.cost_unit;
        d["planner"] = route.plan.planner;
        d["seed"] = seed;
        return result("Route", d);
      },
      ("A Route between start and goal ((x, y, z) m), as `ceilplan plan` with its defaults; figures from the full "
       "model. mode: " +
       oneOf(mission::flightModeNames()) + "; objective: " + oneOf(planner::objectiveNames()) +
       "; planner: " + oneOf(planner::plannerNames()) +
       " ('': the default, BITstar; OMPL's stop at time_limit_s); seed: OMPL's, only the first a process gives "
       "takes effect; lattice_spacing_m: the lattice planners' node spacing; band_fraction: in [0, 1); refine: "
       "post-process the route")
          .c_str(),
      py::arg("env"), py::arg("start"), py::arg("goal"), py::arg("mode") = "ceiling", py::arg("objective") = "charge",
      py::arg("planner") = "", py::arg("time_limit_s") = defaults.time_limit_s,
      py::arg("seed") = mission::PlanningOptions{}.seed, py::arg("lattice_spacing_m") = defaults.lattice.spacing_m,
      py::arg("band_fraction") = defaults.band_fraction, py::arg("refine") = defaults.refine);

  m.def(
      "evaluate",
      [](const PyEnvironment& env, const std::vector<std::vector<double>>& path) {
        std::vector<Eigen::Vector3d> waypoints;
        waypoints.reserve(path.size());
        for (const auto& p : path) waypoints.push_back(point(p, "path point"));
        const mission::RouteCheck check = [&] {
          py::gil_scoped_release release;
          return mission::checkRoute(*env.context, waypoints);
        }();
        py::dict d = evaluationDict(check.evaluation);
        d["valid"] = !check.violation;
        d["violation"] = check.violation ? py::object(py::str(*check.violation)) : py::none();
        d["cost"] = check.cost;
        return result("Evaluation", d);
      },
      "An Evaluation: the figures and the safety (dense re-check) of any path of (x, y, z) points in metres, as "
      "`ceilplan evaluate`",
      py::arg("env"), py::arg("path"));

  py::class_<PyMission>(m, "Mission", "An inspection mission file (docs/missions.md)")
      .def_static(
          "load", [](const std::filesystem::path& path) { return PyMission{io::readMission(path)}; },
          "Reads a mission file with its map, vehicle and battery files (docs/missions.md); raises InputError naming "
          "the file and key",
          py::arg("path"))
      .def_property_readonly(
          "targets", [](const PyMission& self) { return namesOf(self.mission.targets); },
          "The point targets' names, as the file gives them")
      .def_property_readonly(
          "surfaces", [](const PyMission& self) { return namesOf(self.mission.surfaces); },
          "The names of the surfaces to photograph (coverage regions, docs/coverage.md)")
      .def_property_readonly(
          "contact_grids", [](const PyMission& self) { return namesOf(self.mission.contact_grids); },
          "The contact grids' names")
      .def_property_readonly(
          "vehicle", [](const PyMission& self) { return self.mission.vehicle; }, "The mission's Vehicle")
      .def_property_readonly(
          "mode", [](const PyMission& self) { return self.mission.mode; },
          "The file's `mode`: 'ceiling', 'free', 'both', or '' (none): what plan_tour plans without a mode")
      .def_property_readonly(
          "seed", [](const PyMission& self) { return self.mission.planning.seed; },
          "The seed of the tour's order heuristic (plan_tour's default)")
      .def_property(
          "wind", [](const PyMission& self) { return windDict(self.mission.planning.wind); },
          [](PyMission& self, const py::dict& wind) { self.mission.planning.wind = windOf(wind); },
          "The file's `wind:` as a dict {speed_m_s, from_deg, gust_m_s, sheltered_fraction} (calm: speed_m_s 0); "
          "settable with the same keys (speed_m_s and from_deg required), checked as the file's key is")
      .def("__repr__", [](const PyMission& self) {
        const mission::Mission& mission = self.mission;
        return "Mission(" + quoted(py::str(mission.file.string())) +
               ", targets=" + std::to_string(mission.targets.size()) +
               ", surfaces=" + std::to_string(mission.surfaces.size()) +
               ", contact_grids=" + std::to_string(mission.contact_grids.size()) +
               ", mode=" + quoted(py::str(mission.mode)) + ", seed=" + std::to_string(mission.planning.seed) + ")";
      });

  py::class_<PyTour, std::shared_ptr<PyTour>>(m, "Tour",
                                              "An inspection tour in one mode, as `ceilplan tour --mode MODE` plans it "
                                              "(plan_tour); read only")
      .def_property_readonly(
          "mode", [](const PyTour& t) { return mission::flightModeName(t.tour.mode); }, "'ceiling' or 'free'")
      .def_property_readonly(
          "charge_ah", [](const PyTour& t) { return t.tour.plan.charge_ah; },
          "Charge drawn over the whole tour (Ah), dwells included")
      .def_property_readonly(
          "fec", [](const PyTour& t) { return t.tour.plan.fec; },
          "Full equivalent cycles of the flights and their recharges, against the nominal capacity")
      .def_property_readonly(
          "min_soc", [](const PyTour& t) { return t.tour.plan.min_soc; },
          "The lowest state of charge at any landing (0 to 1)")
      .def_property_readonly(
          "duration_s", [](const PyTour& t) { return t.tour.plan.flight_s; },
          "Flight time (s), dwells included, turnarounds between sorties not")
      .def_property_readonly(
          "stops_rechosen", [](const PyTour& t) { return t.tour.stops_rechosen; },
          "Whether the first stops left one no route from home reaches, and they were chosen again")
      .def_property_readonly(
          "sorties", [](const PyTour& t) { return sortieList(t.tour); },
          "The sorties (Sortie) in flying order, with their legs and waypoints, as tour.json and the autopilot files "
          "give them")
      .def_property_readonly(
          "wear",
          [](const PyTour& t) {
            py::dict d;
            for (const mission::PlanWear& w : t.tour.wear) {
              py::dict entry;
              entry["wear_name"] = w.wear_name;
              entry["cycle_wear"] = w.cycle_wear;
              entry["capacity_loss"] = w.capacity_loss;
              d[py::str(w.model)] = entry;
            }
            return d;
          },
          ("The wear of a new pack flying the sorties, per ageing model (" + oneOf(battery::ageingModelNames()) +
           "): wear_name (the model's cycle-wear measure), cycle_wear, capacity_loss (fraction of nominal capacity, "
           "calendar ageing included)")
              .c_str())
      .def_property_readonly(
          "samples", [](const PyTour& t) { return sampleColumns(io::tourPathRows(t.tour), true); },
          "The flight record as Samples: path.csv's rows and columns, every sortie on the tour's clock (t_s from the "
          "first take-off) and a 'recharge' row after each")
      .def_property_readonly(
          "photos",
          [](const PyTour& t) -> py::object {
            if (!t.tour.coverage) return py::none();
            return photoArrays(t.tour.photos);
          },
          "A coverage tour's photos as flown, photos.csv's columns (Photos; None without surfaces)")
      .def_property_readonly(
          "coverage",
          [](const PyTour& t) -> py::object {
            if (!t.tour.coverage || !t.tour.coverage_check) return py::none();
            return result("Coverage", pythonJson(io::coverageJson(*t.tour.coverage, *t.tour.coverage_check)));
          },
          "A coverage tour's coverage.json (Coverage): per region the area, covered area and %, unreachable area, GSD "
          "histogram, uncovered centres, by the independent re-check of the photos flown (None without surfaces)")
      .def(
          "write",
          [](const PyTour& t, const std::filesystem::path& dir, bool export_autopilot) {
            writeTours(dir, {&t}, export_autopilot, t.call);
          },
          "Writes tour.json, path.csv, map views, photos.csv and coverage.json for a coverage tour and, with autopilot "
          "and the mission's origin, the geodetic exports (mission.plan, mission.waypoints, mission.kmz, routes.kml, "
          "routes.geojson; without an origin tour.json's geodetic_exports_skipped names them), as `ceilplan tour`",
          py::arg("dir"), py::arg("autopilot") = true)
      .def("__repr__", [](const PyTour& t) {
        const io::StopCounts counts = io::stopCounts(t.tour);
        return "Tour(mode=" + quoted(py::str(mission::flightModeName(t.tour.mode))) +
               ", targets=" + std::to_string(counts.targets_visited) +
               (t.tour.coverage ? ", photos=" + std::to_string(counts.photos_taken) : std::string()) +
               ", sorties=" + std::to_string(t.tour.plan.sorties.size()) +
               ", charge_ah=" + formatFixed(t.tour.plan.charge_ah, 4) + ", fec=" + formatFixed(t.tour.plan.fec, 4) +
               ", min_soc=" + formatFixed(t.tour.plan.min_soc, 3) +
               ", duration_s=" + formatFixed(t.tour.plan.flight_s, 1) + ")";
      });

  py::class_<PyTourComparison>(m, "TourComparison",
                               "Both modes of a tour over one indexed map, as `ceilplan tour --mode both` plans them "
                               "(plan_tour(mode='both')); read only")
      .def_property_readonly(
          "ceiling", [](const PyTourComparison& c) { return c.ceiling; }, "The ceiling-mode Tour")
      .def_property_readonly(
          "free", [](const PyTourComparison& c) { return c.free; }, "The free-mode Tour")
      .def_property_readonly(
          "table", [](const PyTourComparison& c) { return io::comparisonTable(c.ceiling->tour, c.free->tour); },
          "The side-by-side table `ceilplan tour --mode both` prints and writes as comparison.txt")
      .def_property_readonly(
          "comparison",
          [](const PyTourComparison& c) {
            nlohmann::json json =
                io::comparisonJson(c.ceiling->tour, c.free->tour, io::Provenance::of("python: " + c.call));
            json.erase("provenance");
            return pythonJson(json);
          },
          "comparison.json as a dict: per mode the totals (charge_ah, flight_s, duration_s, fec, min_soc, wear, "
          "duty, sorties, ...) and reduction_pct, ceiling against free, in percent of free mode's")
      .def(
          "write",
          [](const PyTourComparison& c, const std::filesystem::path& dir, bool export_autopilot) {
            writeTours(dir, {c.ceiling.get(), c.free.get()}, export_autopilot, c.call);
          },
          "Writes what `ceilplan tour --mode both --out DIR` writes: each Tour.write's files in DIR/ceiling and "
          "DIR/free, and comparison.txt, comparison.json, report.html and map views of both routes in DIR",
          py::arg("dir"), py::arg("autopilot") = true)
      .def("__repr__", [](const PyTourComparison& c) {
        const mission::SortiePlan &ceiling = c.ceiling->tour.plan, &free = c.free->tour.plan;
        return "TourComparison(charge_ah ceiling=" + formatFixed(ceiling.charge_ah, 4) +
               " free=" + formatFixed(free.charge_ah, 4) + ", fec ceiling=" + formatFixed(ceiling.fec, 4) +
               " free=" + formatFixed(free.fec, 4) + ", sorties ceiling=" + std::to_string(ceiling.sorties.size()) +
               " free=" + std::to_string(free.sorties.size()) + ")";
      });

  m.def(
      "plan_tour",
      [](const PyMission& mission, const std::optional<std::string>& mode, std::optional<std::uint32_t> seed,
         const std::string& planner, const std::string& ageing_model, const std::optional<py::dict>& wind,
         const py::object& progress) -> py::object {
        // The arguments override the mission's settings (Mission::planning), as the CLI's flags do.
        auto planned = std::make_shared<mission::Mission>(mission.mission);
        if (seed) planned->planning.seed = *seed;
        if (wind) planned->planning.wind = windOf(*wind);
        planned->planning.ageing_model = ageing_model;
        planned->planning.validate();  // before indexing the map
        const std::shared_ptr<const mission::Mission> shared_mission = planned;
        mission::TourOptions options;
        options.planner = planner;
        options.validate();  // before indexing the map
        const std::string mode_name = mode ? *mode : mission.mission.mode.empty() ? "ceiling" : mission.mission.mode;
        const std::vector<mission::FlightMode> modes = mission::tourFlightModes(mode_name);
        // As `ceilplan tour`: OMPL's generators seeded from the tour seed (only the first seed of a process counts).
        if (!planner::plannerInfo(options.planner).deterministic()) planner::seedOmpl(planned->planning.seed);
        PythonProgress reporter(progress);
        options.progress = reporter.callback();
        auto [context, tours] = reporter.run([&] {
          auto context = std::make_shared<const mission::PlanningContext>(*shared_mission, options.progress);
          std::vector<mission::TourResult> tours = mission::planTours(*shared_mission, *context, modes, options);
          return std::make_pair(context, std::move(tours));
        });
        const std::string call = "ceilplan.plan_tour(mission, mode='" + mode_name +
                                 "', seed=" + std::to_string(planned->planning.seed) + ", planner='" + planner +
                                 "', ageing_model='" + ageing_model + "')";
        std::vector<std::shared_ptr<PyTour>> results;
        for (mission::TourResult& tour : tours) {
          tour.options.progress = {};  // the callable is the caller's, for this call only
          const std::string name = modes.size() > 1 ? call + "." + mission::flightModeName(tour.mode) : call;
          results.push_back(std::make_shared<PyTour>(PyTour{std::move(tour), shared_mission, context, name}));
        }
        if (results.size() == 1) return py::cast(results.front());
        return py::cast(PyTourComparison{results[0], results[1], call});
      },
      ("Plans the mission's tour as `ceilplan tour` does: point targets, contact grids and surfaces to photograph. "
       "mode: 'ceiling', 'free' or 'both' (None: the mission's `mode`, else 'ceiling'); 'both' plans ceiling and "
       "free mode at once over one indexed map and returns a TourComparison, one mode a Tour. seed: the order "
       "heuristic's "
       "(None: the mission's). planner: the leg planner, " +
       oneOf(planner::plannerNames()) +
       " (the default 'roadmap' is deterministic). ageing_model: the model whose "
       "wear the sortie split minimises, " +
       oneOf(battery::ageingModelNames()) +
       ". wind: None (the mission's `wind:`), or a dict {speed_m_s, from_deg, gust_m_s, sheltered_fraction} as "
       "Mission.wind takes. progress: None, or a callable progress(stage, fraction) called with the GIL held from the "
       "calling thread, "
       "several times a second, while the library works (stage e.g. 'ceiling mode: building the roadmap', fraction "
       "0 to 1, 1 at a stage's end); an exception it raises stops the work and comes out of plan_tour")
          .c_str(),
      py::arg("mission"), py::arg("mode") = py::none(), py::arg("seed") = py::none(), py::arg("planner") = "roadmap",
      py::arg("ageing_model") = mission::PlanningOptions{}.ageing_model, py::arg("wind") = py::none(),
      py::arg("progress") = py::none());

  const io::MapImportOptions import_defaults;  // `ceilplan import`'s defaults too
  m.def(
      "import_map",
      [](const std::filesystem::path& out, const std::optional<std::filesystem::path>& points,
         const std::optional<std::filesystem::path>& mesh, const std::optional<std::filesystem::path>& origins,
         double resolution_m, const std::string& crs, double max_range_m, std::optional<double> free_distance_m,
         const std::string& free_region, std::optional<double> margin_m, const std::string& interior,
         bool skip_non_finite, const std::optional<std::vector<double>>& crop, const py::object& progress) {
        io::MapImportOptions options;
        options.points = points.value_or("");
        options.mesh = mesh.value_or("");
        options.origins = origins.value_or("");
        options.resolution_m = resolution_m;
        options.crs = crs;
        options.max_range_m = max_range_m;
        options.free_distance_m = free_distance_m;
        options.free_region = free_region;
        options.margin_m = margin_m;
        options.interior = interior;
        options.skip_non_finite = skip_non_finite;
        if (crop) options.crop_m = cropBox(*crop);
        options.validate();  // before the output is staged or a file read
        if (out.extension() != ".bt") throw InputError(out.string() + ": an imported map is written as .bt");
        std::filesystem::path summary = out;
        summary += ".json";
        // The rules of `ceilplan import --out`: never replaces an input; the map and its summary appear together.
        io::OutputSet outputs({{"out", out}, {"out's summary", summary}},
                              {{"points", options.points}, {"origins", options.origins}, {"mesh", options.mesh}});
        PythonProgress reporter(progress);
        const io::MapImport imported = reporter.run([&] { return io::importMap(options, reporter.callback()); });
        const io::Provenance provenance = io::Provenance::of("python: ceilplan.import_map('" + out.string() + "', ...)")
                                              .input("points", options.points)
                                              .input("origins", options.origins)
                                              .input("mesh", options.mesh);
        io::writeImportedMap(outputs.path("out"), imported, options, provenance, outputs.path("out's summary"));
        outputs.commit();
        return result("MapImport",
                      pythonJson(io::withProvenance(io::mapImportJson(imported, options, out), provenance)));
      },
      "Builds an OctoMap (.bt) from a point cloud (points: .pcd, .ply, ...; origins: the sensor positions) or a mesh "
      "(mesh: .stl, .obj, .ply, .off, .gltf, .glb, .dae, .fbx) as `ceilplan import` does and writes it with its "
      "summary (<out>.json); returns the summary (MapImport): free_space says what was assumed and what it means for "
      "planning. resolution_m: voxel size; crs: 'EPSG:<code>' of projected data ('': local already); max_range_m: "
      "with origins, the longest ray carved (0: no limit); free_distance_m: without origins, how far from the data "
      "space is assumed free; free_region: 'between' or 'box'; margin_m: around the data; interior: a mesh's inside, "
      "'auto', 'solid', 'hollow' or 'shell'; skip_non_finite: drop NaN points; crop: (xmin, ymin, zmin, xmax, ymax, "
      "zmax) m; progress: None or a callable progress(stage, fraction) (see plan_tour)",
      py::arg("out"), py::kw_only(), py::arg("points") = py::none(), py::arg("mesh") = py::none(),
      py::arg("origins") = py::none(), py::arg("resolution_m") = import_defaults.resolution_m, py::arg("crs") = "",
      py::arg("max_range_m") = import_defaults.max_range_m, py::arg("free_distance_m") = py::none(),
      py::arg("free_region") = import_defaults.free_region, py::arg("margin_m") = py::none(),
      py::arg("interior") = import_defaults.interior, py::arg("skip_non_finite") = false, py::arg("crop") = py::none(),
      py::arg("progress") = py::none());

  const battery::DutyStudyOptions paper;  // the defaults of the study and of `ceilplan duty`
  m.def(
      "duty",
      [](const std::vector<double>& flight_currents_a, double capacity_ah, double charge_current_a, double flight_s,
         double idle_s, double charge_max_s, double soc_start, int missions_per_day, int days,
         std::optional<double> years, double step_s, const std::vector<std::string>& models, double temperature_c,
         const std::string& chemistry, double end_of_life_soh, double woehler_n100, double woehler_k,
         const py::object& progress) {
        battery::DutyStudyOptions options;
        options.flight_currents_a = flight_currents_a;
        options.pack.capacity_ah = capacity_ah;
        options.pack.charge_current_a = charge_current_a;
        options.flight_s = flight_s;
        options.idle_s = idle_s;
        options.charge_max_s = charge_max_s;
        options.soc_start = soc_start;
        options.missions_per_day = missions_per_day;
        options.days = days;
        options.years = years.value_or(0.0);
        options.step_s = step_s;
        options.ageing_models = models;
        options.temperature_c = temperature_c;
        options.chemistry = chemistry;
        options.end_of_life_soh = end_of_life_soh;
        options.woehler.cycles_at_full_depth = woehler_n100;
        options.woehler.exponent = woehler_k;
        options.cell_voltage_of_soc = energy::lipoCellVoltageOfSoc();
        PythonProgress reporter(progress);
        options.progress = reporter.callback();
        const battery::DutyStudyResult study = reporter.run([&] { return battery::runDutyStudy(options); });
        return dutyStudyResult(options, study);
      },
      ("The founding paper's duty study (DutyStudy), as `ceilplan duty` runs it with the same defaults (times in "
       "seconds, currents in A, capacity in Ah, SOC 0 to 1): per case SOC, DoD, FEC and charge, each ageing model's "
       "wear, fade and end of life, reductions against the first case, the first day's samples and the printed "
       "table. models: any of " +
       oneOf(battery::ageingModelNames()) +
       "; years: the projection's span (None: days); woehler_n100, woehler_k: the Woehler curve's cycles at full "
       "depth and exponent; progress: None or a callable progress(stage, fraction) (see plan_tour)")
          .c_str(),
      py::arg("flight_currents_a") = paper.flight_currents_a, py::arg("capacity_ah") = paper.pack.capacity_ah,
      py::arg("charge_current_a") = paper.pack.charge_current_a, py::arg("flight_s") = paper.flight_s,
      py::arg("idle_s") = paper.idle_s, py::arg("charge_max_s") = paper.charge_max_s,
      py::arg("soc_start") = paper.soc_start, py::arg("missions_per_day") = paper.missions_per_day,
      py::arg("days") = paper.days, py::arg("years") = py::none(), py::arg("step_s") = paper.step_s,
      py::arg("models") = paper.ageing_models, py::arg("temperature_c") = paper.temperature_c,
      py::arg("chemistry") = paper.chemistry, py::arg("end_of_life_soh") = paper.end_of_life_soh,
      py::arg("woehler_n100") = paper.woehler.cycles_at_full_depth, py::arg("woehler_k") = paper.woehler.exponent,
      py::arg("progress") = py::none());

  const mission::ProposalOptions proposal_defaults;
  const io::ProposalSettings settings_defaults;
  m.def(
      "propose",
      [](const std::filesystem::path& map, const std::filesystem::path& vehicle, const std::filesystem::path& out,
         const std::optional<std::filesystem::path>& picture, const std::optional<std::vector<double>>& home,
         const std::optional<std::vector<double>>& crop, double min_area_m2, int max_regions, const std::string& camera,
         double gsd_mm_px, double overlap_front, double overlap_side, std::uint32_t seed, const std::string& unknown,
         std::optional<double> unknown_fill_max_m, const py::object& progress) {
        io::ProposalRequest request;
        request.mission_file = out;
        request.picture_file = picture.value_or(std::filesystem::path());
        request.mission_flag = "out";
        request.picture_flag = "picture";
        if (home) request.options.home_m = point(*home, "home");
        if (crop) request.options.crop_m = cropBox(*crop);
        request.options.min_region_area_m2 = min_area_m2;
        request.options.max_regions = max_regions;
        request.settings.map_file = map;
        request.settings.vehicle_file = vehicle;
        request.settings.camera_preset = camera;
        request.settings.gsd_mm_px = gsd_mm_px;
        request.settings.overlap_front_pct = overlap_front;
        request.settings.overlap_side_pct = overlap_side;
        request.settings.seed = seed;
        request.settings.unknown = unknownSpace(unknown, unknown_fill_max_m);
        const std::string call =
            "python: ceilplan.propose('" + map.string() + "', '" + vehicle.string() + "', '" + out.string() + "')";
        PythonProgress reporter(progress);
        const mission::MissionProposal proposal = reporter.run(
            [&] { return io::proposeMissionFiles(request, io::Provenance::of(call), reporter.callback()); });
        py::list regions;
        for (const mission::ProposedRegion& region : proposal.regions) {
          py::dict d;
          d["name"] = region.name;
          d["box_min"] = std::vector<double>{region.box_m.min().x(), region.box_m.min().y(), region.box_m.min().z()};
          d["box_max"] = std::vector<double>{region.box_m.max().x(), region.box_m.max().y(), region.box_m.max().z()};
          d["area_m2"] = region.area_m2;
          d["elements"] = region.elements;
          regions.append(d);
        }
        py::dict d;
        d["regions"] = regions;
        d["home"] = std::vector<double>{proposal.home_m.x(), proposal.home_m.y(), proposal.home_m.z()};
        d["home_given"] = proposal.home_given;
        d["home_height_m"] =
            std::isfinite(proposal.home_height_m) ? py::object(py::float_(proposal.home_height_m)) : py::none();
        d["dropped_regions"] = proposal.dropped_regions;
        d["dropped_area_m2"] = proposal.dropped_area_m2;
        d["overhead_area_m2"] = proposal.overhead_area_m2;
        d["too_low_area_m2"] = proposal.too_low_area_m2;
        d["min_room_below_m"] = proposal.min_room_below_m;
        d["mission"] = request.mission_file;
        d["picture"] = request.picture_file;
        return result("Proposal", d);
      },
      ("Proposes a coverage mission from a map, as `ceilplan propose`: its overhead surfaces as regions and a home; "
       "writes the mission file and a plan-view picture (.svg) and returns what was proposed (Proposal). home: "
       "(x, y, z) m (None: proposed); crop: (xmin, ymin, zmin, xmax, ymax, zmax) m; camera: a preset, " +
       cameraPresetNames() +
       "; gsd_mm_px: the required ground sampling distance; overlap_front, overlap_side: percent; unknown: "
       "'occupied', 'free' or 'fill' (unknown_fill_max_m with 'fill'); progress: None or a callable progress(stage, "
       "fraction) (see plan_tour)")
          .c_str(),
      py::arg("map"), py::arg("vehicle"), py::arg("out"), py::arg("picture") = py::none(), py::arg("home") = py::none(),
      py::arg("crop") = py::none(), py::arg("min_area_m2") = proposal_defaults.min_region_area_m2,
      py::arg("max_regions") = proposal_defaults.max_regions, py::arg("camera") = settings_defaults.camera_preset,
      py::arg("gsd_mm_px") = settings_defaults.gsd_mm_px,
      py::arg("overlap_front") = settings_defaults.overlap_front_pct,
      py::arg("overlap_side") = settings_defaults.overlap_side_pct, py::arg("seed") = settings_defaults.seed,
      py::arg("unknown") = "occupied", py::arg("unknown_fill_max_m") = py::none(), py::arg("progress") = py::none());
}
