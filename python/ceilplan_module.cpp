// The `ceilplan` Python module: the library's maps, vehicles, routes and tours with numpy arrays
// for samples. docs/python.md walks through a session.

#include "ceilplan/ceilplan.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

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

py::dict gapsDict(const environment::SurfaceGaps& gaps) {
  py::dict d;
  d["nearest_gap_m"] = infinityAsNone(gaps.nearest_gap_m);
  d["coverage"] = gaps.coverage;
  d["mean_gap_m"] = infinityAsNone(gaps.mean_gap_m);
  return d;
}

// Columns of samples as numpy arrays: t_s, x, y, z, current_a, soc (and speed, gaps).
py::dict sampleArrays(const std::vector<std::vector<planner::PathSample>>& sorties,
                      const std::vector<double>& offsets_s) {
  std::size_t n = 0;
  for (const auto& samples : sorties) n += samples.size();
  py::array_t<double> t(n), x(n), y(n), z(n), speed(n), gap(n), current(n), soc(n);
  py::array_t<int> sortie(n);
  std::size_t k = 0;
  for (std::size_t s = 0; s < sorties.size(); ++s)
    for (const planner::PathSample& sample : sorties[s]) {
      t.mutable_at(k) = offsets_s[s] + sample.t_s;
      x.mutable_at(k) = sample.position_m.x();
      y.mutable_at(k) = sample.position_m.y();
      z.mutable_at(k) = sample.position_m.z();
      speed.mutable_at(k) = sample.speed_m_s;
      gap.mutable_at(k) = std::isfinite(sample.ceiling_gap_m) ? sample.ceiling_gap_m : std::nan("");
      current.mutable_at(k) = sample.current_a;
      soc.mutable_at(k) = sample.soc;
      sortie.mutable_at(k) = static_cast<int>(s) + 1;
      ++k;
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
  d["sortie"] = sortie;
  return d;
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
  d["samples"] = sampleArrays({e.samples}, {0.0});
  return d;
}

// The photos of a coverage tour as flown (photos.csv's columns) as numpy arrays, regions as a list.
py::dict photoArrays(const std::vector<mission::PhotoRow>& rows) {
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
  return d;
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

py::dict dutyStudyDict(const battery::DutyStudyOptions& options, const battery::DutyStudyResult& result) {
  py::list cases;
  for (const battery::DutyStudyCase& c : result.cases) {
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
    cases.append(d);
  }
  py::dict comparison_days;
  for (std::size_t m = 0; m < result.comparison_days.size(); ++m)
    comparison_days[py::str(options.ageing_models[m])] = result.comparison_days[m];
  py::dict d;
  d["study_days"] = result.study_days;
  d["span"] = options.spanText();
  d["cases"] = cases;
  d["comparison_days"] = comparison_days;
  d["table"] = io::dutyStudyTable(options, result);
  return d;
}

}  // namespace

PYBIND11_MODULE(ceilplan, m) {
  m.doc() = "ceilplan: battery-wear-aware inspection planning for multirotors flying under ceilings";
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

  py::class_<mission::Vehicle>(m, "Vehicle", "A multirotor: its shape and its energy model")
      .def_static("default", &mission::Vehicle::defaultQuad, "The built-in quadrotor (maps/vehicles/quad.yaml)")
      .def_static(
          "load", [](const std::filesystem::path& file) { return io::readVehicle(file); }, py::arg("path"))
      .def_readonly("name", &mission::Vehicle::name)
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
          "Pack current (A); a gap of None is free air", py::arg("ceiling_gap_m") = py::none(),
          py::arg("coverage") = 1.0, py::arg("ground_gap_m") = py::none(), py::arg("speed_m_s") = 0.0,
          py::arg("climb_m_s") = 0.0, py::arg("soc") = py::none());

  py::class_<PyEnvironment>(m, "Environment", "A map indexed for a vehicle and a battery")
      .def_static(
          "load",
          [](const std::filesystem::path& path, std::optional<mission::Vehicle> vehicle,
             std::optional<std::filesystem::path> battery, const std::string& unknown,
             std::optional<double> unknown_fill_max_m) {
            mission::PlanningOptions options;
            options.unknown = unknownSpace(unknown, unknown_fill_max_m);
            const mission::Vehicle flown = vehicle.value_or(mission::Vehicle::defaultQuad());
            const mission::BatterySpec pack = io::readBatteryOrDefault(battery.value_or(""), flown);
            py::gil_scoped_release release;  // loading and indexing a map takes seconds
            return PyEnvironment{std::make_shared<mission::PlanningContext>(environment::OccupancyMap::load(path),
                                                                            flown, pack, options)};
          },
          py::arg("path"), py::arg("vehicle") = py::none(), py::arg("battery") = py::none(),
          py::arg("unknown") = "occupied", py::arg("unknown_fill_max_m") = py::none())
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
            return d;
          },
          "Gaps above and below each rotor, clearance and validity with the body centre at (x, y, z)", py::arg("x"),
          py::arg("y"), py::arg("z"))
      .def_property_readonly("resolution_m",
                             [](const PyEnvironment& self) { return self.context->map().resolution_m(); });

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
        return d;
      },
      "Plans one route as `ceilplan plan` does, with its defaults; figures from the full model", py::arg("env"),
      py::arg("start"), py::arg("goal"), py::arg("mode") = "ceiling", py::arg("objective") = "charge",
      py::arg("planner") = "", py::arg("time_limit_s") = defaults.time_limit_s,
      py::arg("seed") = mission::PlanningOptions{}.seed, py::arg("lattice_spacing_m") = defaults.lattice.spacing_m,
      py::arg("band_fraction") = defaults.band_fraction, py::arg("refine") = defaults.refine);

  m.def(
      "evaluate",
      [](const PyEnvironment& env, const std::vector<std::vector<double>>& path) {
        std::vector<Eigen::Vector3d> waypoints;
        for (const auto& p : path) waypoints.push_back(point(p, "path point"));
        const mission::RouteCheck check = [&] {
          py::gil_scoped_release release;
          return mission::checkRoute(*env.context, waypoints);
        }();
        py::dict d = evaluationDict(check.evaluation);
        d["valid"] = !check.violation;
        d["violation"] = check.violation ? py::object(py::str(*check.violation)) : py::none();
        d["cost"] = check.cost;
        return d;
      },
      "Figures and safety (dense re-check) of any path of (x, y, z) points", py::arg("env"), py::arg("path"));

  py::class_<PyMission>(m, "Mission", "An inspection mission file (docs/missions.md)")
      .def_static(
          "load", [](const std::filesystem::path& path) { return PyMission{io::readMission(path)}; }, py::arg("path"))
      .def_property_readonly("targets",
                             [](const PyMission& self) {
                               std::vector<std::string> names;
                               for (const auto& target : self.mission.targets) names.push_back(target.name);
                               return names;
                             })
      .def_property_readonly("surfaces",
                             [](const PyMission& self) {
                               std::vector<std::string> names;
                               for (const auto& surface : self.mission.surfaces) names.push_back(surface.name);
                               return names;
                             })
      .def_property_readonly("contact_grids",
                             [](const PyMission& self) {
                               std::vector<std::string> names;
                               for (const auto& grid : self.mission.contact_grids) names.push_back(grid.name);
                               return names;
                             })
      .def_property_readonly("vehicle", [](const PyMission& self) { return self.mission.vehicle; })
      .def_property_readonly("seed", [](const PyMission& self) { return self.mission.planning.seed; });

  py::class_<PyTour>(m, "Tour", "An inspection tour in one mode")
      .def_property_readonly("mode", [](const PyTour& t) { return mission::flightModeName(t.tour.mode); })
      .def_property_readonly("charge_ah", [](const PyTour& t) { return t.tour.plan.charge_ah; })
      .def_property_readonly("fec", [](const PyTour& t) { return t.tour.plan.fec; })
      .def_property_readonly("min_soc", [](const PyTour& t) { return t.tour.plan.min_soc; })
      .def_property_readonly("duration_s", [](const PyTour& t) { return t.tour.plan.flight_s; })
      .def_property_readonly(
          "stops_rechosen", [](const PyTour& t) { return t.tour.stops_rechosen; },
          "whether the first stops left one no route from home reaches, and they were chosen again")
      .def_property_readonly("sorties",
                             [](const PyTour& t) {
                               py::list list;
                               for (const mission::Sortie& sortie : t.tour.plan.sorties) {
                                 py::dict d;
                                 std::vector<std::string> names;
                                 for (int k : sortie.targets) names.push_back(t.tour.names[k]);
                                 d["targets"] = names;
                                 d["charge_ah"] = sortie.charge_ah;
                                 d["dod"] = sortie.dod;
                                 d["duration_s"] = sortie.flight_s;
                                 d["min_soc"] = sortie.lowest_soc;
                                 d["reason"] = sortie.reason;
                                 list.append(d);
                               }
                               return list;
                             })
      .def_property_readonly("wear",
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
                             })
      .def_property_readonly("samples",
                             [](const PyTour& t) {
                               std::vector<std::vector<planner::PathSample>> sorties;
                               std::vector<double> offsets;
                               for (const mission::SortieRecord& sortie : t.tour.record.sorties) {
                                 sorties.push_back(sortie.samples);
                                 offsets.push_back(sortie.takeoff_s);
                               }
                               return sampleArrays(sorties, offsets);
                             })
      .def_property_readonly(
          "photos",
          [](const PyTour& t) -> py::object {
            if (!t.tour.coverage) return py::none();
            return photoArrays(t.tour.photos);
          },
          "A coverage tour's photos as flown, photos.csv's columns as arrays (None without surfaces)")
      .def_property_readonly(
          "coverage",
          [](const PyTour& t) -> py::object {
            if (!t.tour.coverage || !t.tour.coverage_check) return py::none();
            return pythonJson(io::coverageJson(*t.tour.coverage, *t.tour.coverage_check));
          },
          "A coverage tour's coverage.json: per region the area, covered area and %, unreachable area, GSD "
          "histogram, uncovered centres, by the independent re-check of the photos flown (None without surfaces)")
      .def(
          "write",
          [](const PyTour& t, const std::filesystem::path& dir, bool export_autopilot) {
            std::optional<io::Autopilot> autopilot;
            if (export_autopilot) autopilot = io::Autopilot::PX4;
            const std::string call = "python: " + t.call + ".write('" + dir.string() +
                                     "', autopilot=" + (export_autopilot ? "True" : "False") + ")";
            const io::Provenance provenance =
                io::tourProvenance(io::Provenance::of(call), *t.mission, t.tour.planning.seed);
            // The rules of `ceilplan tour --out`: replaced whole, only if ceilplan wrote it (or it is empty).
            io::OutputSet out({{"dir", dir, true}}, {{"the mission's map", t.mission->map_file},
                                                     {"the mission's vehicle", t.mission->vehicle_file}});
            io::writeTourDirectory(out.path(), t.tour, *t.mission, t.context->environment(), autopilot, provenance);
            out.commit();
          },
          "Writes tour.json, path.csv, map views, photos.csv and coverage.json for a coverage tour and, with autopilot "
          "and the mission's origin, the geodetic exports (mission.plan, mission.waypoints, mission.kmz, routes.kml, "
          "routes.geojson; without an origin tour.json's geodetic_exports_skipped names them), as `ceilplan tour`",
          py::arg("dir"), py::arg("autopilot") = true);

  m.def(
      "plan_tour",
      [](const PyMission& mission, const std::string& mode, std::optional<std::uint32_t> seed,
         const std::string& planner, const std::string& ageing_model) {
        // The arguments override the mission's settings (Mission::planning), as the CLI's flags do.
        auto planned = std::make_shared<mission::Mission>(mission.mission);
        if (seed) planned->planning.seed = *seed;
        planned->planning.ageing_model = ageing_model;
        planned->planning.validate();  // before indexing the map
        const std::shared_ptr<const mission::Mission> shared_mission = planned;
        mission::TourOptions options;
        options.planner = planner;
        options.validate();
        const mission::FlightMode flight_mode = mission::flightModeFromName(mode);
        py::gil_scoped_release release;
        auto context = std::make_shared<const mission::PlanningContext>(*shared_mission);
        mission::TourResult tour = mission::planTour(*shared_mission, *context, flight_mode, options);
        const std::string call = "ceilplan.plan_tour(mission, mode='" + mode +
                                 "', seed=" + std::to_string(planned->planning.seed) + ", planner='" + planner +
                                 "', ageing_model='" + ageing_model + "')";
        return PyTour{std::move(tour), shared_mission, context, call};
      },
      "Plans the mission's tour in one mode, as `ceilplan tour` does: point targets, contact grids and surfaces to "
      "photograph",
      py::arg("mission"), py::arg("mode") = "ceiling", py::arg("seed") = py::none(), py::arg("planner") = "roadmap",
      py::arg("ageing_model") = mission::PlanningOptions{}.ageing_model);

  const io::MapImportOptions import_defaults;  // `ceilplan import`'s defaults too
  m.def(
      "import_map",
      [](const std::filesystem::path& out, const std::optional<std::filesystem::path>& points,
         const std::optional<std::filesystem::path>& mesh, const std::optional<std::filesystem::path>& origins,
         double resolution_m, const std::string& crs, double max_range_m, std::optional<double> free_distance_m,
         const std::string& free_region, std::optional<double> margin_m, const std::string& interior,
         bool skip_non_finite, const std::optional<std::vector<double>>& crop) {
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
        const io::MapImport imported = [&] {
          py::gil_scoped_release release;
          return io::importMap(options);
        }();
        const io::Provenance provenance = io::Provenance::of("python: ceilplan.import_map('" + out.string() + "', ...)")
                                              .input("points", options.points)
                                              .input("origins", options.origins)
                                              .input("mesh", options.mesh);
        io::writeImportedMap(outputs.path("out"), imported, options, provenance, outputs.path("out's summary"));
        outputs.commit();
        return pythonJson(io::withProvenance(io::mapImportJson(imported, options, out), provenance));
      },
      "Builds an OctoMap (.bt) from a point cloud or a mesh as `ceilplan import` does and writes it with its summary "
      "(<out>.json); returns the summary: free_space says what was assumed and what it means for planning",
      py::arg("out"), py::kw_only(), py::arg("points") = py::none(), py::arg("mesh") = py::none(),
      py::arg("origins") = py::none(), py::arg("resolution_m") = import_defaults.resolution_m, py::arg("crs") = "",
      py::arg("max_range_m") = import_defaults.max_range_m, py::arg("free_distance_m") = py::none(),
      py::arg("free_region") = import_defaults.free_region, py::arg("margin_m") = py::none(),
      py::arg("interior") = import_defaults.interior, py::arg("skip_non_finite") = false, py::arg("crop") = py::none());

  const battery::DutyStudyOptions paper;  // the defaults of the study and of `ceilplan duty`
  m.def(
      "duty",
      [](const std::vector<double>& flight_currents_a, double capacity_ah, double charge_current_a, double flight_s,
         double idle_s, double charge_max_s, double soc_start, int missions_per_day, int days,
         std::optional<double> years, double step_s, const std::vector<std::string>& models, double temperature_c,
         const std::string& chemistry, double end_of_life_soh, double woehler_n100, double woehler_k) {
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
        const battery::DutyStudyResult result = [&] {
          py::gil_scoped_release release;
          return battery::runDutyStudy(options);
        }();
        return dutyStudyDict(options, result);
      },
      "The founding paper's duty study, as `ceilplan duty` runs it with the same defaults (times in seconds): per "
      "case SOC, DoD, FEC and charge, each ageing model's wear, fade and end of life, reductions against the first "
      "case, the first day's samples and the printed table",
      py::arg("flight_currents_a") = paper.flight_currents_a, py::arg("capacity_ah") = paper.pack.capacity_ah,
      py::arg("charge_current_a") = paper.pack.charge_current_a, py::arg("flight_s") = paper.flight_s,
      py::arg("idle_s") = paper.idle_s, py::arg("charge_max_s") = paper.charge_max_s,
      py::arg("soc_start") = paper.soc_start, py::arg("missions_per_day") = paper.missions_per_day,
      py::arg("days") = paper.days, py::arg("years") = py::none(), py::arg("step_s") = paper.step_s,
      py::arg("models") = paper.ageing_models, py::arg("temperature_c") = paper.temperature_c,
      py::arg("chemistry") = paper.chemistry, py::arg("end_of_life_soh") = paper.end_of_life_soh,
      py::arg("woehler_n100") = paper.woehler.cycles_at_full_depth, py::arg("woehler_k") = paper.woehler.exponent);

  const mission::ProposalOptions proposal_defaults;
  const io::ProposalSettings settings_defaults;
  m.def(
      "propose",
      [](const std::filesystem::path& map, const std::filesystem::path& vehicle, const std::filesystem::path& out,
         std::optional<std::filesystem::path> picture, std::optional<std::vector<double>> home,
         std::optional<std::vector<double>> crop, double min_area_m2, int max_regions, const std::string& camera,
         double gsd_mm_px, double overlap_front, double overlap_side, std::uint32_t seed, const std::string& unknown,
         std::optional<double> unknown_fill_max_m) {
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
        const mission::MissionProposal proposal = [&] {
          py::gil_scoped_release release;
          return io::proposeMissionFiles(request, io::Provenance::of(call));
        }();
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
        return d;
      },
      "Proposes a coverage mission from a map, as `ceilplan propose`: its overhead surfaces as regions and a home; "
      "writes the mission file and a plan-view picture (.svg) and returns what was proposed",
      py::arg("map"), py::arg("vehicle"), py::arg("out"), py::arg("picture") = py::none(), py::arg("home") = py::none(),
      py::arg("crop") = py::none(), py::arg("min_area_m2") = proposal_defaults.min_region_area_m2,
      py::arg("max_regions") = proposal_defaults.max_regions, py::arg("camera") = settings_defaults.camera_preset,
      py::arg("gsd_mm_px") = settings_defaults.gsd_mm_px,
      py::arg("overlap_front") = settings_defaults.overlap_front_pct,
      py::arg("overlap_side") = settings_defaults.overlap_side_pct, py::arg("seed") = settings_defaults.seed,
      py::arg("unknown") = "occupied", py::arg("unknown_fill_max_m") = py::none());
}
