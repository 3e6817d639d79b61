// The -ball_* options. See ball_options.hpp.
#include "io/ball_options.hpp"

#include "io/cor_table_file.hpp"

#include <cmath>
#include <string>

namespace beamimpact {

namespace {

// The characterisation options: k1 from (-ball_contact_time, -ball_test_speed), n from -ball_cor
// or -ball_cor_table, each refused with the parameter it replaces.
struct BallCharacterisation {
  PetscReal cor = 0, contact_time = 0, test_speed = 0;
  PetscBool set_cor = PETSC_FALSE, set_tau = PETSC_FALSE, set_vt = PETSC_FALSE, set_table = PETSC_FALSE;
  char      table[PETSC_MAX_PATH_LEN] = "";
  bool      any() const { return set_cor || set_tau || set_vt || set_table; }
  const char *first() const { return set_cor ? "-ball_cor" : set_tau ? "-ball_contact_time" : set_vt ? "-ball_test_speed" : "-ball_cor_table"; }
};

PetscErrorCode BallCharacterise(MPI_Comm comm, const BallCharacterisation &ch, PetscBool setk1, PetscBool setn, BallParams *b)
{
  PetscFunctionBeginUser;
  // Two sources for one parameter.
  PetscCheck(!(ch.set_tau && setk1), comm, PETSC_ERR_ARG_INCOMP,
             "-ball_contact_time and -ball_k1 both set the loading coefficient k1: give either -ball_k1 or the characterisation -ball_contact_time with -ball_test_speed (k1 follows from them)");
  PetscCheck(!(ch.set_vt && setk1), comm, PETSC_ERR_ARG_INCOMP,
             "-ball_test_speed and -ball_k1 both set the loading coefficient k1: give either -ball_k1 or the characterisation -ball_contact_time with -ball_test_speed (k1 follows from them)");
  PetscCheck(!(ch.set_cor && setn), comm, PETSC_ERR_ARG_INCOMP,
             "-ball_cor and -ball_n both set the unloading exponent n: give either -ball_n or -ball_cor (n = (m+1)/e^2 - 1)");
  PetscCheck(!(ch.set_table && setn), comm, PETSC_ERR_ARG_INCOMP,
             "-ball_cor_table and -ball_n both set the unloading exponent n: with a table, n follows e(v) of each contact's approach speed; drop -ball_n");
  PetscCheck(!(ch.set_table && ch.set_cor), comm, PETSC_ERR_ARG_INCOMP,
             "-ball_cor_table and -ball_cor both set the coefficient of restitution: with a table, e at the test speed is the table's; drop -ball_cor");
  PetscCheck(ch.set_tau == ch.set_vt, comm, PETSC_ERR_ARG_INCOMP, "%s needs %s: the contact time is measured at a test speed (k1 follows from the two)",
             ch.set_tau ? "-ball_contact_time" : "-ball_test_speed", ch.set_tau ? "-ball_test_speed" : "-ball_contact_time");
  // Ranges.
  if (ch.set_cor)
    PetscCheck(std::isfinite(ch.cor) && ch.cor > 0 && ch.cor <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-ball_cor %g is not allowed: the rigid-wall coefficient of restitution e must be in (0, 1] (e = 1: no loss)", (double)ch.cor);
  if (ch.set_tau) {
    PetscCheck(std::isfinite(ch.contact_time) && ch.contact_time > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_contact_time %g is not allowed: the rigid-wall contact time must be > 0 (s)",
               (double)ch.contact_time);
    PetscCheck(std::isfinite(ch.test_speed) && ch.test_speed > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_test_speed %g is not allowed: the test speed must be > 0 (m/s)", (double)ch.test_speed);
  }
  if (ch.set_table) {
    std::string why;
    PetscCheck(CorTableRead(ch.table, &b->cor_table, &why), comm, PETSC_ERR_FILE_UNEXPECTED, "%s", why.c_str());
  }
  // n, then k1 (which needs e at the test speed).
  if (ch.set_cor) b->n = BallExponentFromCor(b->m, ch.cor);
  if (ch.set_table) b->n = BallExponentAt(*b, b->speed); // the first contact's; each later contact sets its own
  if (ch.set_tau) {
    b->contact_time = ch.contact_time;
    b->test_speed   = ch.test_speed;
    b->cor          = BallCorAt(*b, ch.test_speed);
    b->k1           = BallK1FromContactTime(b->mass, b->m, b->cor, ch.contact_time, ch.test_speed);
    PetscCheck(std::isfinite(b->k1) && b->k1 > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-ball_contact_time %g s at -ball_test_speed %g m/s gives k1 = %g N/m^m, which is not a usable number: check the contact time, the speed and -ball_m %g", (double)ch.contact_time,
               (double)ch.test_speed, (double)b->k1, (double)b->m);
  } else if (ch.set_cor) b->cor = ch.cor;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode BallParamsFromOptions(MPI_Comm comm, BallParams *b)
{
  PetscEnum law = (PetscEnum)b->law;
  PetscBool setk = PETSC_FALSE, setk1 = PETSC_FALSE, setm = PETSC_FALSE, setn = PETSC_FALSE;
  PetscBool set_radius = PETSC_FALSE;
  BallCharacterisation ch;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Ball: mass, speed and contact law (SI units)", "beamimpact");
  PetscCall(PetscOptionsReal("-ball_mass", "Ball mass m_b (kg)", "", b->mass, &b->mass, NULL));
  PetscCall(PetscOptionsReal("-ball_speed", "Incident speed v_i (m/s)", "", b->speed, &b->speed, NULL));
  PetscCall(PetscOptionsEnum("-ball_law", "Contact law", "", ContactLawNames, law, &law, NULL));
  PetscCall(PetscOptionsReal("-ball_k", "Linear spring stiffness k (N/m); -ball_law linear", "", b->k, &b->k, &setk));
  PetscCall(PetscOptionsReal("-ball_k1", "Hysteresis loading coefficient k1 (N/m^m); -ball_law hysteresis", "", b->k1, &b->k1, &setk1));
  PetscCall(PetscOptionsReal("-ball_m", "Hysteresis loading exponent m; -ball_law hysteresis", "", b->m, &b->m, &setm));
  PetscCall(PetscOptionsReal("-ball_n", "Hysteresis unloading exponent n; -ball_law hysteresis", "", b->n, &b->n, &setn));
  PetscCall(PetscOptionsReal("-ball_cor", "Rigid-wall coefficient of restitution e in (0, 1]; sets n = (m+1)/e^2 - 1 (instead of -ball_n); -ball_law hysteresis", "", ch.cor, &ch.cor, &ch.set_cor));
  PetscCall(PetscOptionsReal("-ball_contact_time", "Rigid-wall contact time tau (s, first touch to separation) at -ball_test_speed; sets k1 (instead of -ball_k1); -ball_law hysteresis", "",
                             ch.contact_time, &ch.contact_time, &ch.set_tau));
  PetscCall(PetscOptionsReal("-ball_test_speed", "Speed (m/s) at which -ball_contact_time (and -ball_cor) were measured against a rigid wall", "", ch.test_speed, &ch.test_speed, &ch.set_vt));
  PetscCall(PetscOptionsString("-ball_cor_table", "File of rows 'v e': wall COR against approach speed (m/s); n follows e(v) at each contact start (instead of -ball_n, -ball_cor)", "", ch.table,
                               ch.table, sizeof(ch.table), &ch.set_table));
  PetscCall(PetscOptionsReal("-ball_radius", "Ball radius (m): a compression beyond it is flagged as physically absurd (a sweep's summary counts such points; default: none, no check)", "", b->radius, &b->radius, &set_radius));
  PetscCall(PetscOptionsReal("-ball_loss_factor", "Factor applied to the ACOR for ball losses (reported as acor_corrected)", "", b->loss_factor, &b->loss_factor, NULL));
  PetscOptionsEnd();
  b->law = (ContactLawKind)law;

  PetscCheck(b->mass > 0 && std::isfinite(b->mass), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_mass %g is not allowed: it must be > 0 (kg)", (double)b->mass);
  PetscCheck(b->speed > 0 && std::isfinite(b->speed), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_speed %g is not allowed: it must be > 0 (m/s)", (double)b->speed);
  PetscCheck(!set_radius || (b->radius > 0 && std::isfinite(b->radius)), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_radius %g is not allowed: it must be > 0 (m)", (double)b->radius);
  PetscCheck(b->loss_factor > 0 && b->loss_factor <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_loss_factor %g is not allowed: it must be in (0, 1]", (double)b->loss_factor);
  if (b->law == ContactLawKind::Linear) {
    PetscCheck(!(setk1 || setm || setn || ch.any()), comm, PETSC_ERR_ARG_INCOMP, "%s is a hysteresis parameter but -ball_law is linear: use -ball_k, or -ball_law hysteresis",
               setk1 ? "-ball_k1" : setm ? "-ball_m" : setn ? "-ball_n" : ch.first());
    PetscCheck(b->k > 0 && std::isfinite(b->k), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_k %g is not allowed: it must be > 0 (N/m)", (double)b->k);
  } else {
    PetscCheck(!setk, comm, PETSC_ERR_ARG_INCOMP, "-ball_k is the linear spring stiffness but -ball_law is hysteresis: use -ball_k1, -ball_m, -ball_n");
    PetscCheck(b->k1 > 0 && std::isfinite(b->k1), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_k1 %g is not allowed: it must be > 0", (double)b->k1);
    PetscCheck(b->m >= 1 && std::isfinite(b->m), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_m %g is not allowed: the loading exponent must be >= 1", (double)b->m);
    PetscCall(BallCharacterise(comm, ch, setk1, setn, b));
    PetscCheck(b->n >= b->m, comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_n %g is not allowed: the unloading exponent must be >= m = %g (energy can only be lost)", (double)b->n, (double)b->m);
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact
