// The PETSc options the program advertises. See petsc_options.hpp. Defaults are PETSc's, or
// the program's where it sets one (LU through KSPPREONLY, the step of each type); "" where the
// program chooses from the problem (-ts_dt).
#include "solvers/petsc_options.hpp"

namespace beamimpact {

namespace {

OptionSpec WithRangeText(OptionSpec s, const char *text)
{
  s.range_text = text;
  return s;
}

} // namespace

const OptionModule &PetscSolverOptionTable()
{
  static const OptionModule m = {
    "petsc",
    "PETSc integrator and solver options beamimpact advertises (read by PETSc for the -ts_type that uses them)",
    {
      // the integrator and its step
      OptionChoice("-ts_type", "Integrator: any type that can roll back a step (docs: Choosing an integrator)",
                   {"rk", "cn", "theta", "beuler", "bdf", "alpha", "alpha2", "arkimex", "rosw", "irk", "modal"}, "rk"),
      OptionReal("-ts_dt", "s",
                 "Time step (fixed, or the first of an adaptive run); default: the program's (explicit: min(0.9 "
                 "dt_max, contact time/200))",
                 "", Positive()),
      OptionReal("-ts_rtol", "1", "Relative tolerance of the local error (adaptive steps)", "1e-4", NonNegative()),
      OptionReal("-ts_atol", "1", "Absolute tolerance of the local error (adaptive steps)", "1e-4", NonNegative()),
      OptionReal("-ts_max_time", "s", "Refused: the driver stops the run; use -impact_max_time", ""),
      OptionInt("-ts_max_steps", "Refused: the driver steps the TS; use -impact_max_time", ""),
      OptionInt("-ts_max_reject", "Step rejections allowed before a step fails", "10", NonNegative()),
      OptionInt("-ts_max_snes_failures", "Nonlinear solve failures allowed", "1"),
      OptionFlag("-ts_monitor", "Print each step (time, step size)"),
      OptionFlag("-ts_view", "Print the TS set-up at the end of the run"),
      // adaptive steps
      OptionChoice("-ts_adapt_type", "Step size controller", {"none", "basic", "dsp"}, "basic"),
      OptionReal("-ts_adapt_dt_min", "s", "Smallest step the controller takes", "1e-20", Positive()),
      OptionReal("-ts_adapt_dt_max", "s",
                 "Largest step the controller takes (the program caps it at 1/8 of the contact time)", "1e20",
                 Positive()),
      OptionReal("-ts_adapt_safety", "1", "Safety factor of the step size controller", "0.9", Positive()),
      OptionReal("-ts_adapt_reject_safety", "1", "Extra safety factor after a rejected step", "0.5", Positive()),
      [] {
        OptionSpec s = OptionList("-ts_adapt_clip", "1", "Admissible decrease, increase factors of the step", 2, 2,
                                  Positive());
        s.def        = "0.1,10";
        return s;
      }(),
      OptionFlag("-ts_adapt_monitor", "Print the controller's choices"),
      OptionFlag("-ts_adapt_always_accept", "Accept every step (no rejection)"),
      // the types' own options
      OptionText("-ts_rk_type",
                 "Runge-Kutta tableau of -ts_type rk: 3bs, 4, 5dp, 5bs, 8vr, ... (1fe, 2a, 2b, 5f are refused: "
                 "unstable for undamped oscillation)",
                 "3bs"),
      WithRangeText(OptionReal("-ts_theta_theta", "1",
                               "theta of -ts_type theta (0.5: Crank-Nicolson, 1: backward Euler)", "0.5",
                               Between(0.5, 1)),
                    "in [0.5, 1] (below 0.5 the method is unstable)"),
      OptionFlag("-ts_theta_endpoint", "-ts_type theta: the endpoint form (the trapezoidal rule at theta = 0.5)"),
      OptionFlag("-ts_theta_initial_guess_extrapolate", "-ts_type theta: extrapolate the Newton initial guess"),
      OptionReal("-ts_alpha_radius", "1",
                 "Spectral radius at infinite frequency of -ts_type alpha and alpha2 (1: no high-frequency damping)",
                 "1", Between(0, 1)),
      OptionReal("-ts_alpha_alpha_m", "1",
                 "-ts_type alpha2: weight of A_n+1 in the acceleration of the residual (default from -ts_alpha_radius)",
                 ""),
      OptionReal("-ts_alpha_alpha_f", "1",
                 "-ts_type alpha2: weight of X_n+1, V_n+1 (and time) in the residual (default from -ts_alpha_radius)",
                 ""),
      OptionReal("-ts_alpha_gamma", "1", "-ts_type alpha2: Newmark gamma (second order: 1/2 + alpha_m - alpha_f)", ""),
      OptionReal("-ts_alpha_beta", "1", "-ts_type alpha2: Newmark beta (second order: (1 + alpha_m - alpha_f)^2/4)",
                 ""),
      OptionChoice("-ts_alpha_restart",
                   "-ts_type alpha2: acceleration at the first step and after a restart: shifted (order 2 under any "
                   "restarts) or exact (a(t), unit mass)",
                   {"shifted", "exact"}, "shifted"),
      OptionInt("-ts_bdf_order", "Order of -ts_type bdf (up to 2 for this undamped problem)", "2", Between(1, 6)),
      OptionText("-ts_arkimex_type",
                 "Tableau of -ts_type arkimex: 1bee, a2, l2, ars122, 2c, 2d, 2e, prssp2, 3, bpr3, ars443, 4, 5", "3"),
      OptionFlag("-ts_arkimex_fully_implicit", "-ts_type arkimex: treat the right-hand side implicitly too"),
      OptionText("-ts_rosw_type", "Tableau of -ts_type rosw: ra34pw2, ra3pw, rodas3, sandu3, shamp4, 2m, 2p, ...",
                 "ra34pw2"),
      OptionFlag("-ts_rosw_recompute_jacobian", "-ts_type rosw: recompute the Jacobian at every stage"),
      OptionText("-ts_irk_type", "Tableau of -ts_type irk (gauss)", "gauss"),
      OptionInt("-ts_irk_nstages", "Stages of -ts_type irk", "2", AtLeast(1)),
      WithRangeText(OptionInt("-ts_modal_order",
                              "Order of -ts_type modal: 2 (force linear over the step, trapezoidal collocation) or 4 "
                              "(force quadratic, Lobatto collocation at 0, h/2, h); the beam's modes are exact for the "
                              "force",
                              "4", Between(2, 4)),
                    "2 or 4"),
      // the nonlinear and linear solvers of the implicit types
      OptionText("-snes_type", "Nonlinear solver (ksponly: one linear solve per stage; not with alpha2)", "newtonls"),
      OptionReal("-snes_rtol", "1", "Relative decrease of the residual norm that stops Newton", "1e-8", NonNegative()),
      OptionReal("-snes_atol", "1", "Residual norm that stops Newton", "1e-50", NonNegative()),
      OptionReal("-snes_stol", "1", "Relative step length that stops Newton", "1e-8", NonNegative()),
      OptionInt("-snes_max_it", "Newton iterations allowed", "50", AtLeast(1)),
      OptionInt("-snes_lag_jacobian", "Rebuild the Jacobian every this many Newton iterations (-1: never)", "1"),
      OptionText("-snes_linesearch_type", "Line search of newtonls: bt, basic, l2, cp", "bt"),
      OptionText("-snes_convergence_test", "Newton's convergence test (default, skip)", "default"),
      OptionFlag("-snes_monitor", "Print each Newton iteration"),
      OptionFlag("-snes_converged_reason", "Print why Newton stopped"),
      OptionFlag("-snes_error_if_not_converged", "Stop with an error when Newton fails"),
      OptionText("-ksp_type", "Linear solver (the program's: preonly, a direct solve)", "preonly"),
      OptionReal("-ksp_rtol", "1", "Relative tolerance of an iterative linear solver", "1e-5", NonNegative()),
      OptionReal("-ksp_atol", "1", "Absolute tolerance of an iterative linear solver", "1e-50", NonNegative()),
      OptionInt("-ksp_max_it", "Iterations of an iterative linear solver", "10000", AtLeast(1)),
      OptionFlag("-ksp_monitor", "Print each linear iteration"),
      OptionFlag("-ksp_converged_reason", "Print why the linear solver stopped"),
      OptionText("-pc_type",
                 "Preconditioner (the program's: shell, the beam's LU kept per step size and the contact by "
                 "Sherman-Morrison; lu: the whole Jacobian refactored at each change)",
                 "shell"),
      OptionText("-pc_factor_mat_ordering_type", "Ordering of the LU factorisation (nd, rcm, natural, ...)", "nd"),
      OptionText("-pc_factor_mat_solver_type",
                 "LU package (petsc; mumps on more than one rank; superlu_dist on one rank only: PETSc 3.18 frees its "
                 "grid twice in parallel)",
                 "petsc"),
      // the modes' eigensolver (SLEPc, prefix modes_)
      OptionText("-modes_eps_type", "-task modes: SLEPc eigensolver", "krylovschur"),
      OptionReal("-modes_eps_tol", "1", "-task modes: eigensolver tolerance", "1e-12", Positive()),
      OptionInt("-modes_eps_max_it", "-task modes: eigensolver iterations", "1000", AtLeast(1)),
      OptionFlag("-modes_eps_monitor", "-task modes: print the eigensolver's iterations"),
      OptionFlag("-modes_eps_view", "-task modes: print the eigensolver's set-up"),
      OptionText("-modes_st_type", "-task modes: spectral transformation (the program's: sinvert)", "sinvert"),
    },
    true,
    {"-ts_",  "-snes_",      "-ksp_",      "-pc_",       "-all_ksp_",  "-mat_",      "-vec_",
     "-dm_",  "-modes_eps_", "-modes_st_", "-modes_bv_", "-modes_ds_", "-modes_rg_", "-modes_fn_",
     "-eps_", "-st_",        "-bv_",       "-ds_",       "-rg_",       "-fn_"},
  };
  return m;
}

} // namespace beamimpact
