// The problem of -task design (studies/design.hpp), shared by its parts: its inputs and their
// parsing (design_spec.cpp), the designs' values through the case batch and their differences
// (design_eval.cpp), TAO (design_solve.cpp) and the outputs (design_output.cpp). TAO sees the
// variables scaled to u in [0, 1] (FitParameter's scale).
#pragma once

#include "studies/case_batch.hpp"
#include "studies/fit_data.hpp"

#include <petsctao.h>

#include <map>
#include <string>
#include <vector>

namespace beamimpact {

struct DesignSettings {
  std::string variables, studies, objective,
    constraints;                 // -design_variables, -design_studies, -design_objective, -design_constraints as given
  bool        maximize = true;   // -design_goal maximize (else minimize)
  bool        central  = false;  // -design_differences central (else forward)
  PetscReal   step     = 1e-4;   // -design_difference_step: relative step of a variable (1)
  PetscReal   pivot    = 0.1524; // m, -design_pivot: the rig's pivot from x = 0 for inertia_pivot
  PetscReal   xtol     = 1e-4;   // -design_xtol: bqnls/blmvm stop when no scaled variable moves more (1)
  std::string options_output;    // -design_options_output ("" none)
  PetscBool   quiet = PETSC_FALSE, restart = PETSC_FALSE; // -design_quiet, -design_restart
  PetscInt    stop_after = 0; // -design_stop_after: stop after this many runs (tests of the resume)
};

// A study of each design: a name and its settings, the product of its axes (e.g. the rig:
// beam_pivot=0.1524, ball_speed=60.8, impact_x=0.55:0.75:5).
struct DesignStudy {
  std::string              name;
  std::string              spec;  // as given
  std::vector<CaseOptions> cases; // the settings of each point
};

enum class DesignReduce {
  Value,
  Max,
  Min,
  Mean
};

// A number of a design: a reduction of a column over a study's points, or a number of the bat.
struct DesignQuantity {
  std::string  text; // as written: "max(bbcor@rig)", "drop"
  DesignReduce reduce = DesignReduce::Value;
  int          study  = -1; // index into studies; -1: a number of the bat (bat)
  size_t       column = 0;  // index into the batch's columns
  std::string  bat;         // mass, drop, balance, inertia_knob, inertia_pivot, inertia_cm, length, diameter
  std::string  unit;
};

struct DesignConstraint {
  DesignQuantity q;
  bool           upper = true; // q <= bound (else q >= bound)
  double         bound = 0;    // q's unit
  double         scale = 1;    // TAO's c = (bound - q)/scale >= 0 (|bound|, or 1 for 0)
  std::string    Name() const; // a dataset's name: "max_bbcor_rig"
};

// The numbers of one design.
struct DesignValues {
  std::vector<double> p; // the variables (their units)
  double              objective = 0;
  std::vector<double> constraint;      // each constraint's quantity (its unit)
  bool                feasible = true; // no constraint violated by more than -tao_catol (DesignViolated)
};

// One design evaluated, for /design.
struct DesignRecord {
  DesignValues v;
  PetscInt     iteration = -1;   // TAO's iteration when it was asked for
  int          role      = 1;    // 0 an iterate (TAO's monitor saw it), 2 a point TAO asked for that no iteration
                                 // took (a line search's trial), 1 only a difference's point
  double kkt = NAN, cnorm = NAN; // at TAO's iterates: the gradient (of the Lagrangian) and constraint norms
};

struct DesignProblem {
  MPI_Comm                              world = MPI_COMM_NULL;
  PetscMPIInt                           rank  = 0;
  DesignSettings                        settings;
  std::vector<FitParameter>             vars;
  std::vector<DesignStudy>              studies;
  std::vector<std::string>              columns; // the impact's columns the batch keeps
  DesignQuantity                        objective;
  std::vector<DesignConstraint>         constraints;
  CaseBatch                             batch;
  std::vector<DesignRecord>             history;
  std::map<std::vector<double>, size_t> known;         // u -> index into history
  PetscInt                              iteration = 0; // TAO's current iteration
  std::vector<double>                   u_prev;        // the last iterate (the step test)
  std::string                           stop;          // the program's test that stopped TAO ("" none)
  double catol = 1e-4; // -tao_catol as TAO read it (1): a design is feasible when every scaled constraint c >= -catol
  bool   options_checked = false;
  bool   bat_numbers     = false; // some quantity is a number of the bat

  size_t              n() const { return vars.size(); }
  size_t              m() const { return constraints.size(); }
  std::vector<double> ToP(const std::vector<double> &u) const;
  std::vector<double> ToU(const std::vector<double> &p) const;
};

// design_spec.cpp: the -design_* options; the studies, the objective and the constraints parsed
// (*why the reason one is refused, naming the option and the text).
PetscErrorCode DesignSettingsFromOptions(MPI_Comm comm, const std::string &output, DesignSettings *s);
bool           DesignParseStudies(const std::string &text, std::vector<DesignStudy> *studies, std::string *why);
bool           DesignParseQuantity(const std::string &text, const std::vector<DesignStudy> &studies,
                                   std::vector<std::string> *columns, DesignQuantity *q, std::string *why);
bool           DesignParseConstraints(const std::string &text, const std::vector<DesignStudy> &studies,
                                      std::vector<std::string> *columns, std::vector<DesignConstraint> *constraints,
                                      std::string *why);
// The bat's numbers a quantity may name, with their units.
const std::vector<std::pair<std::string, std::string>> &DesignBatNumbers();

// design_eval.cpp. Collective: the values of the designs at the scaled points us, all in one batch
// (each design's studies' points; a failed run is an error naming the design and the point).
PetscErrorCode DesignEvaluate(DesignProblem &d, const std::vector<std::vector<double>> &us,
                              std::vector<DesignValues> *vals, int role);
// Collective: at u, the value and the gradients over u of the objective (as TAO minimises it:
// -objective when maximising) and of TAO's constraints c = (bound - q)/scale (or q - bound), by
// forward or central differences (a variable at a bound steps inward), in one batch.
PetscErrorCode DesignGradient(DesignProblem &d, const std::vector<double> &u, bool central, double step, double *f,
                              std::vector<double> *g, std::vector<double> *c, std::vector<double> *J);
// TAO's constraints of a design's values (>= 0 holds).
std::vector<double> DesignTaoConstraints(const DesignProblem &d, const DesignValues &v);
// The constraints a design violates by more than d.catol (c < -catol: Q <= B read as Q <= B + catol |B|), by index.
std::vector<size_t> DesignViolated(const DesignProblem &d, const DesignValues &v);

// design_solve.cpp. Collective: TAO from the start to the optimum.
struct DesignResult {
  std::vector<double>      p; // the optimum (the variables' units)
  DesignValues             v; // its numbers
  std::string              tao_type, reason;
  PetscInt                 iterations = 0;
  double                   kkt = NAN, cnorm = NAN; // the final gradient (of the Lagrangian) norm and constraint norm
  std::vector<std::string> active,
    at_bound;                        // the constraints within 1e-3 of their bound (relative), the variables at a bound
  std::vector<size_t>      violated; // the constraints the optimum violates beyond -tao_catol (empty: feasible)
  long                     best_feasible = -1;  // the history's best feasible design (index; -1 none)
  double                   gatol         = NAN; // -tao_gatol as TAO used it (1)
  PetscInt                 max_it        = 0;   // -tao_max_it
  std::string              almm_type;           // almm's formulation (classic, phr; "" another solver)
  std::vector<std::string> notes;               // about TAO's options: one with no effect, a tolerance almm replaced
  bool                     feasible() const { return violated.empty(); }
};
PetscErrorCode DesignTaoDefaults(Tao tao, bool constrained);
PetscErrorCode DesignSolve(DesignProblem &d, DesignResult *res);

// design_output.cpp.
PetscErrorCode DesignCheckOutputs(MPI_Comm comm, const std::string &output, const DesignSettings &s);
PetscErrorCode DesignPrintSummary(const DesignProblem &d, const DesignResult &res);
PetscErrorCode DesignWriteOutputs(DesignProblem &d, const DesignResult &res, const std::string &output);

} // namespace beamimpact
