// The results file of -task flight. See flight_h5.hpp.
#include "io/flight_h5.hpp"

#include "io/results_h5.hpp"

#include <hdf5.h>

namespace beamimpact {

PetscErrorCode FlightRunRecordBuild(const FlightParams &p, const FlightModel &m, const FlightSolveParams &s, const FlightResult &r, RunRecord *rec)
{
  PetscFunctionBeginUser;
  PetscCall(RunRecordProgram(rec));
  rec->add("flight_speed", p.launch.speed);
  rec->add("flight_angle", p.launch.angle);
  rec->add("flight_direction", p.launch.direction);
  rec->add("flight_spin", p.launch.backspin);
  rec->add("flight_sidespin", p.launch.sidespin);
  rec->add("flight_height", p.launch.height);
  rec->add("flight_ball_mass", p.ball.mass);
  rec->add("flight_ball_radius", p.ball.radius);
  rec->add("flight_cd0", p.aero.cd0);
  rec->add("flight_cd_spin", p.aero.cd_spin);
  rec->add("flight_cl0", p.aero.cl0);
  rec->add("flight_cl1", p.aero.cl1);
  rec->add("flight_cl2", p.aero.cl2);
  rec->add("flight_spin_decay_time", p.aero.spin_decay_time);
  rec->add("flight_constants", p.aero.constants == FlightConstants::Calculator ? "calculator" : "exact");
  rec->add("flight_gravity", p.gravity);
  rec->add("flight_series_dt", s.series_dt);
  rec->add("air_temperature", p.air.temperature);
  rec->add("air_pressure", p.air.pressure);
  rec->add("air_humidity", p.air.humidity);
  rec->add("air_elevation", p.air.elevation);
  rec->add("air_density_given", p.air.density >= 0 ? 1 : 0);
  // Derived: the density used, K (1/m) and the spin vector (rad/s), the integrator.
  rec->add("air_density", m.rho);
  rec->add("flight_drag_constant", m.K);
  rec->add("flight_spin_x", m.w[0]);
  rec->add("flight_spin_y", m.w[1]);
  rec->add("flight_spin_z", m.w[2]);
  rec->add("ts_type", r.ts_type);
  rec->add("flight_ts_rtol", r.rtol);
  rec->add("flight_ts_atol", r.atol);
  rec->add("flight_ts_fixed_step", r.fixed_step ? r.dt : 0.0); // s; 0: adaptive, by the two tolerances
  PetscFunctionReturn(0);
}

// /results (one row) and /series of the flight r, into the open file.
static PetscErrorCode FlightWriteGroups(hid_t file, const std::string &path, const FlightResult &r)
{
  PetscFunctionBeginUser;
  const FlightLanding &l = r.landing;
  hid_t                g = H5Gcreate2(file, "results", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /results in %s", path.c_str());
  const struct {
    const char *name, *unit;
    PetscReal   value;
  } columns[] = {
    {"distance", "m", l.distance},         {"apex", "m", r.apex},
    {"apex_time", "s", r.apex_time},       {"hang_time", "s", l.hang_time},
    {"landing_speed", "m/s", l.landing_speed}, {"landing_angle", "deg", l.landing_angle},
    {"landing_x", "m", l.landing_x},       {"landing_y", "m", l.landing_y},
    {"bearing", "deg", l.bearing},         {"landing_residual", "m", r.landing_residual},
    {"wall_time", "s", r.wall_time},
  };
  for (const auto &c : columns) PetscCall(H5WriteDataset1D(g, c.name, {c.value}, c.unit));
  PetscCall(H5WriteDatasetInt1D(g, "steps", {(long long)r.steps}, "1"));
  PetscCall(H5WriteDatasetInt1D(g, "rejected_steps", {(long long)r.rejected_steps}, "1"));
  PetscCall(H5WriteDatasetInt1D(g, "locate_steps", {(long long)r.locate_steps}, "1"));
  PetscCall(H5WriteDatasetInt1D(g, "function_evals", {(long long)r.function_evals}, "1"));
  H5Gclose(g);
  const FlightSeries &q = r.series;
  g                     = H5Gcreate2(file, "series", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /series in %s", path.c_str());
  PetscCall(H5WriteDataset1D(g, "time", q.t, "s"));
  PetscCall(H5WriteDataset1D(g, "x", q.x, "m"));
  PetscCall(H5WriteDataset1D(g, "y", q.y, "m"));
  PetscCall(H5WriteDataset1D(g, "z", q.z, "m"));
  PetscCall(H5WriteDataset1D(g, "vx", q.vx, "m/s"));
  PetscCall(H5WriteDataset1D(g, "vy", q.vy, "m/s"));
  PetscCall(H5WriteDataset1D(g, "vz", q.vz, "m/s"));
  PetscCall(H5WriteDataset1D(g, "spin", q.spin, "rad/s"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

PetscErrorCode ResultsWriteFlightFile(MPI_Comm comm, const std::string &path, const RunRecord &record, const FlightResult &r)
{
  PetscFunctionBeginUser;
  PetscCall(H5ResultsFileWrite(comm, path, record, [&](long long file) -> PetscErrorCode { // whole or not at all
    PetscFunctionBeginUser;
    PetscCall(FlightWriteGroups((hid_t)file, path, r));
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

} // namespace beamimpact
