// The arithmetic of rate-and-state friction (docs/physics.md "Rate-and-state friction"),
// free of any method: the sinh-regularised coefficient (Lapusta et al. 2000; Rice & Ben-Zion
// 1996)
//   mu(V, theta) = a asinh[ V / (2 V*) exp(psi / a) ],   psi = f0 + b ln(V* theta / D_c),
// the state laws (Dieterich's aging law and Ruina's slip law) integrated exactly at a constant
// slip rate over a step, their steady state, and the implicit solve of the slip rate against
// an impedance,
//   tau_lock - eta V = sigma mu(|V|, theta) sign(V),
// that every method makes at each node and step (its eta is the method's own: the radiation
// damping of the boundary-integral method, the node mass over dt dx of the finite elements).
// V is a slip rate magnitude where the text says |V|; theta is in seconds.
#pragma once

#include "solver/params.hpp"

namespace slipfront::rate_state {

using StateLaw = StateEvolution; // aging or slip (solver/params.hpp)

// The numbers of the law at one node.
struct Parameters {
  double a = 0.0125;    // direct effect
  double b = 0.0172;    // evolution effect
  double D_c = 0.037;   // characteristic slip [m]
  double f0 = 0.6;      // reference coefficient (steady state at V*)
  double v_star = 1e-6; // reference slip rate V* [m/s]
};

// mu(V, theta) for V >= 0. Written through ln z, z = V/(2 V*) exp(psi/a), so that neither
// exp(psi/a) nor z^2 overflows: asinh z = ln z + ln(1 + sqrt(1 + z^-2)).
double coefficient(const Parameters& p, double slip_rate, double theta);

// d mu / dV = a / sqrt(V^2 + c^2) with c = 2 V* exp(-psi/a) (the slip rate at which the
// sinh regularisation bends the logarithm).
double coefficient_slope(const Parameters& p, double slip_rate, double theta);

// The state theta after dt at the constant slip rate V >= 0 (exact solutions):
//   aging: theta = D_c/V + (theta0 - D_c/V) exp(-V dt/D_c)          (theta0 + dt at V = 0)
//   slip:  ln theta = exp(-V dt/D_c) ln theta0 + (1 - exp(-V dt/D_c)) ln(D_c/V)
//                                                                  (theta0 at V = 0)
double evolve_state(StateLaw law, const Parameters& p, double theta, double slip_rate, double dt);

// Steady state at V > 0: theta_ss = D_c / V (both laws), and
// mu_ss(V) = a asinh[ V/(2 V*) exp((f0 + b ln(V*/V))/a) ].
double steady_state_theta(const Parameters& p, double slip_rate);
double steady_state_coefficient(const Parameters& p, double slip_rate);

// The theta at which mu(V, theta) = mu (the initial state of SCEC TPV101: the strength
// equals the initial shear stress at the initial slip rate). V > 0, mu > 0.
double theta_for_coefficient(const Parameters& p, double slip_rate, double mu);

// The slip rate V of  tau_lock - eta V = sigma mu(|V|, theta) sign(V)  (eta > 0, sigma >= 0,
// the normal stress seen by friction): V has the sign of tau_lock and |V| lies in
// (0, |tau_lock|/eta]. Solved by Newton's iteration in ln V (rate_state_math.cpp says why it
// converges from any start); `guess` (e.g. the last step's |V|) only speeds it up. The
// traction is then tau_lock - eta V.
struct SlipRateSolve {
  double slip_rate = 0; // V, signed
  int iterations = 0;
};
SlipRateSolve solve_slip_rate(const Parameters& p, double theta, double sigma, double eta,
                              double tau_lock, double guess = 0.0);

} // namespace slipfront::rate_state
