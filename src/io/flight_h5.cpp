// The results file of -task flight. See flight_h5.hpp.
#include "io/flight_h5.hpp"

#include "io/h5_dims.hpp"
#include "io/results_h5.hpp"

#include <hdf5.h>

namespace beamimpact {

PetscErrorCode FlightRunRecordBuild(const FlightParams &p, const FlightModel &m, const FlightSolveParams &s,
                                    const FlightResult &r, RunRecord *rec)
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

const std::vector<FlightResultColumn> &FlightResultColumns()
{
  using R                                            = const FlightResult &;
  static const std::vector<FlightResultColumn> table = {
    {"distance", "m", "the carry: launch point to landing, horizontal", false,
     [](R r) -> double { return r.landing.distance; }},
    {"apex", "m", "the highest point above the ground (the launch height when launched downward)", false,
     [](R r) -> double { return r.apex; }},
    {"apex_time", "s", "when the ball is highest", false, [](R r) -> double { return r.apex_time; }},
    {"hang_time", "s", "time from launch to landing", false, [](R r) -> double { return r.landing.hang_time; }},
    {"landing_speed", "m/s", "the ball's speed at the landing", false,
     [](R r) -> double { return r.landing.landing_speed; }},
    {"landing_angle", "deg", "the landing's direction below the horizontal", false,
     [](R r) -> double { return r.landing.landing_angle; }},
    {"landing_x", "m", "the landing point's x: to the right, seen from the launch point looking down the field", false,
     [](R r) -> double { return r.landing.landing_x; }},
    {"landing_y", "m", "the landing point's y: down the field (the launch direction at -flight_direction 0)", false,
     [](R r) -> double { return r.landing.landing_y; }},
    {"bearing", "deg", "the landing point's direction from the y axis toward +x, seen from the launch point", false,
     [](R r) -> double { return r.landing.bearing; }},
    {"landing_residual", "m", "|z| of the located landing state", false,
     [](R r) -> double { return r.landing_residual; }},
    {"wall_time", "s", "wall-clock time of the flight's integration", false, [](R r) -> double { return r.wall_time; }},
    {"steps", "1", "accepted steps", true, [](R r) -> double { return (double)r.steps; }},
    {"rejected_steps", "1", "steps rejected by the error controller", true,
     [](R r) -> double { return (double)r.rejected_steps; }},
    {"locate_steps", "1", "the landing's re-steps (located onto z = 0)", true,
     [](R r) -> double { return (double)r.locate_steps; }},
    {"function_evals", "1", "right-hand side evaluations", true,
     [](R r) -> double { return (double)r.function_evals; }},
  };
  return table;
}

// /results (one row) and /series of the flight r, into the open file.
static PetscErrorCode FlightWriteGroups(hid_t file, const std::string &path, const FlightResult &r)
{
  PetscFunctionBeginUser;
  hid_t g = H5Gcreate2(file, "results", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /results in %s", path.c_str());
  for (const FlightResultColumn &c : FlightResultColumns()) {
    if (c.integer) PetscCall(H5WriteDatasetInt1D(g, c.name, {(long long)c.get(r)}, c.unit));
    else PetscCall(H5WriteDataset1D(g, c.name, {(PetscReal)c.get(r)}, c.unit));
  }
  PetscCall(H5DimsTable(g, "flight")); // one row: the flight
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
  PetscCall(H5DimsTable(g, "time"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

PetscErrorCode ResultsWriteFlightFile(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                      const FlightResult &r)
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
