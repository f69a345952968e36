// Parameters of one rupture simulation. Every default is the paper's scene
// (Kammer et al. 2014, Sec. 2; docs/physics.md "The scene"). The job JSON of api/ maps onto these
// structs one to one; the solver itself knows nothing of JSON.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace slipfront {

// Linear isotropic elastic solid in plane strain.
struct Material {
  double density = 1.0;       // rho [kg/m^3]
  double young_modulus = 2.5; // E [Pa]
  double poisson_ratio = 0.25;

  double shear_modulus() const { return young_modulus / (2.0 * (1.0 + poisson_ratio)); }
  double lame_lambda() const {
    return young_modulus * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
  }
  // Plane-strain wave speeds: c_p = sqrt((lambda + 2 mu)/rho), c_s = sqrt(mu/rho).
  double p_wave_speed() const {
    return std::sqrt((lame_lambda() + 2.0 * shear_modulus()) / density);
  }
  double s_wave_speed() const { return std::sqrt(shear_modulus() / density); }
  // The particle velocity a shear stress drives in a plane S wave, stress / (rho c_s): the
  // slip-speed scale of a load (the divergence check's, and the derived thresholds' of
  // api/scene_defaults.hpp).
  double particle_velocity(double stress) const { return stress / (density * s_wave_speed()); }
};

// Domain [x_min, x_min + width) x [0, height], periodic in x1, on a rigid plane at x2 = 0.
struct Geometry {
  double width = 40.0;
  double height = 20.0;
  bool auto_height = false; // "height": "auto": smallest h free of top reflections (mesh_size.hpp)
  double x_min = -10.0;
  double nodes_per_meter = 40.0; // n_d; the element size is 1/n_d
  int pml_elements = 20;         // top_boundary "pml": the layer's thickness in elements
};

// Top boundary condition of the perturbation field.
enum class TopBoundary {
  traction,  // keeps the remote traction (free surface for the perturbation)
  absorbing, // Lysmer-Kuhlemeyer dashpots: sigma.n = -rho c v (normal c_p, tangential c_s)
  pml,       // a perfectly matched layer of Geometry::pml_elements rows above the height,
             // ended by the dashpots (solver/fe/absorbing_layer.hpp, docs/physics.md)
};

// Remote uniform load (the initial, uniform, stuck state).
struct Loading {
  double normal_stress = -0.0150; // tau2_0 [Pa], negative = compressive
  double shear_stress = 0.0105;   // tau1_0 [Pa], drives the solid towards +x1
};

// How the regularisation ODE is advanced over a step (solver/interface/friction/
// strength_update.hpp has the formulas, docs/physics.md the accuracy of each).
enum class StrengthUpdate {
  exponential_ramp, // exact for |V| frozen and p linear over the step: second order, stable
  exponential,      // exact for |V| and p frozen (p of the step's end): first order, stable
  explicit_euler,   // forward Euler: unstable once dt k > 2 (for failure studies)
};

// The numbers of the friction law at one interface node: the job's uniform values, which
// `profiles` may override along x1. Each law reads only its own (the others are inert); the
// laws say which (solver/interface/friction/, one file each).
struct FrictionValues {
  double mu = 0.75;     // constant coefficient (coulomb, prakash_clifton)
  double mu_s = 0.75;   // static coefficient (slip_weakening)
  double mu_d = 0.5;    // dynamic coefficient (slip_weakening), <= mu_s
  double D_c = 1e-3;    // slip-weakening distance [m]
  double L = 5e-5;      // characteristic length of the slip-scale regularisation [m]
  double v_star = 1e-4; // reference velocity V* of the slip-scale regularisation [m/s]
  double t_star = 1e-3; // time of the time-scale regularisation [s]
  // Rate-and-state friction (rate_and_state); D_c and v_star are its characteristic slip and
  // reference slip rate.
  double a = 0.01;                 // direct effect
  double b = 0.015;                // evolution effect
  double f0 = 0.6;                 // steady-state coefficient at V*
  double theta = 10.0;             // initial state [s] (initial_state "theta")
  double initial_slip_rate = 1e-6; // [m/s]
};

// The state law of rate-and-state friction (docs/physics.md "Rate-and-state friction").
enum class StateEvolution {
  aging, // d theta/dt = 1 - |V| theta / D_c
  slip,  // d theta/dt = -(|V| theta / D_c) ln(|V| theta / D_c)
};

// Where the initial state of rate-and-state friction comes from.
enum class InitialState {
  steady_state, // theta = D_c / V_ini
  theta,        // the value `theta` (and its profiles)
  stress,       // the theta whose strength at V_ini equals the initial shear stress (SCEC TPV101)
};

// The friction a job chose: its coefficient law and its regularisation by their job JSON
// names (the tables of solver/interface/friction/friction_laws.cpp hold the laws; nothing
// else compares these names), and the laws' choices.
struct Friction : FrictionValues {
  std::string law = "prakash_clifton";
  // The regularisation of the laws that let the job choose it (prakash_clifton's is always
  // the slip scale).
  std::string regularization = "none";
  StrengthUpdate update = StrengthUpdate::exponential_ramp;
  StateEvolution state_evolution = StateEvolution::aging;  // rate_and_state
  InitialState initial_state = InitialState::steady_state; // rate_and_state
};

enum class NucleationType {
  ellipse,            // the moving ellipse of the paper's appendix A (after Cochard & Rice 2000)
  overstressed_patch, // a uniform initial shear stress inside [x1_min, x1_max]
  stress_perturbation // a smooth shear-stress increase in space and time (SCEC TPV101)
};

// How the rupture is started (docs/physics.md "Nucleation"). enabled = false: not at all.
struct Nucleation {
  bool enabled = true;
  NucleationType type = NucleationType::ellipse;
  double a = 0.6;     // a_ell [m]
  double b = 3.6;     // b_ell [m]
  double v = 0.825;   // v_ell [m/s]
  double alpha = 0.8; // largest relative reduction of the normal load
  // The overstressed patch: the initial shear stress [Pa] in the closed interval [x1_min, x1_max].
  double x1_min = -0.5, x1_max = 0.5;
  double shear_stress = 0.012;
  // The stress perturbation: Delta tau(x1, t) = shear_stress_increase F(r) G(t), r = |x1 - x1|,
  // F(r) = exp(r^2/(r^2 - R^2)) for r < R, G(t) = exp((t - T)^2/(t (t - 2T))) for 0 < t < T, 1
  // after (docs/physics.md "Nucleation").
  double x1 = 0.0;                     // centre [m]
  double radius = 3000.0;              // R [m]
  double shear_stress_increase = 25e6; // Delta tau_0 [Pa]
  double rise_time = 1.0;              // T [s]
  bool ellipse() const { return enabled && type == NucleationType::ellipse; }
  bool patch() const { return enabled && type == NucleationType::overstressed_patch; }
  bool perturbation() const { return enabled && type == NucleationType::stress_perturbation; }
};

// An override of the initial stresses and the friction values along x1 (docs/physics.md
// "Profiles"), applied after the uniform values, in the order given: piecewise constant, or
// with a smooth ramp of width w on each side of the interval, where the weight falls from 1
// to 0 by SCEC TPV101's boxcar, B(d) = (1 + tanh(w/(d - w) + w/d)) / 2 at a distance d < w
// from the interval (the value there is old + B (new - old)).
struct Profile {
  double x1_min = -std::numeric_limits<double>::infinity(); // closed interval [x1_min, x1_max]
  double x1_max = std::numeric_limits<double>::infinity();
  bool outside = false;                              // apply to x1 < x1_min or x1 > x1_max instead
  double ramp = 0.0;                                 // w [m]; 0: piecewise constant
  std::optional<double> shear_stress, normal_stress; // [Pa]
  std::vector<std::pair<double FrictionValues::*, double>> friction; // (value, number)
  bool covers(double x1) const { return weight(x1) > 0.0; }
  // The share of the profile's values at x1: 1 where it applies, 0 where it does not.
  double weight(double x1) const {
    const double d = std::max({x1_min - x1, x1 - x1_max, 0.0}); // distance from the interval
    double inside = d == 0.0 ? 1.0 : 0.0;
    if (d > 0.0 && d < ramp) inside = 0.5 * (1.0 + std::tanh(ramp / (d - ramp) + ramp / d));
    return outside ? 1.0 - inside : inside;
  }
};

struct TimeControl {
  double duration = 16.0;     // simulated time [s]
  double safety_factor = 0.5; // dt = safety_factor * stable step of the discrete system
  bool stop_on_arrest = true; // end the run once the rupture has arrested (see arrest rule)
  double arrest_window = 1.0; // [s] the front must stand still and the interface be quiet this long
};

// What the interface records hold (the metrics always use every node and every step).
struct OutputSampling {
  double interval = 0.02; // time between stored samples [s]; rounded to whole steps
  int space_stride = 1;   // store every k-th interface node
};

struct Probes {
  double arrival_x1 = 11.0;      // arrival_time_at_probe
  double spectrum_x1 = 6.0;      // tau_s(t) spectrum for the spectral L_c estimate
  double front_threshold = 1e-6; // slip velocity that defines the front [m/s]
};

// On-fault stations (docs/hdf5-layout.md "/stations"): the interface recorded every step at
// each x1, linearly between the two nodes around it, and its rupture time.
struct Stations {
  std::vector<double> x1; // inside [x_min, x_min + width); empty: no stations
  // |V| [m/s] whose first crossing is the rupture time; a job that gives none takes its
  // probe.front_threshold (api/scene_defaults.hpp), the paper's 1e-6 m/s here.
  double rupture_threshold = 1e-6;
};

// An extra traction applied at the interface (for verification scenes, e.g. a uniform
// tensile step). Returns (t1, t2) [Pa] acting on the solid at (x1, t); t2 > 0 pulls the
// solid away from the rigid plane.
struct InterfaceTraction {
  double t1 = 0.0;
  double t2 = 0.0;
};
using ExtraInterfaceLoad = std::function<InterfaceTraction(double x1, double t)>;

// The numerical method, by its name: the job's "method", the metrics' and the result file's
// (docs/physics.md "Methods"). What a method is, supports and costs is its entry in the
// registry of methods (solver/methods.hpp); a result always says which one produced it.
class Method {
public:
  constexpr Method() = default; // the paper's finite elements
  // `name` must outlive every copy: a literal, or a registered method's name.
  constexpr explicit Method(std::string_view name) : name_(name) {}
  constexpr std::string_view name() const { return name_; }
  constexpr bool operator==(const Method&) const = default;

  // The built-in methods (solver/fe/, solver/spectral/).
  static const Method finite_element; // "fe": Q4 elements of the block, explicit central
                                      // differences (the paper's)
  static const Method spectral_bi;    // "spectral_bi": the elastic half-space by the spectral
                                      // boundary-integral method

private:
  std::string_view name_ = "fe";
};
inline constexpr Method Method::finite_element{"fe"};
inline constexpr Method Method::spectral_bi{"spectral_bi"};

// Options of the spectral boundary-integral method (docs/spectral-bi.md).
struct SpectralOptions {
  double time_step_factor = 0.5; // beta: dt = beta dx / c_s
  double memory_periods = 8.0;   // q: mode k keeps q periods 2 pi / (|k| c_s) of its history
  int corrector_passes = 1;      // passes of the local solve after the predictor (0 = none)
};

// Options of the finite-element method (docs/physics.md "Mesh-scale damping").
struct FeOptions {
  // zeta: a stiffness-proportional (Kelvin-Voigt) damping force -a K v with a = zeta dx / c_s,
  // so it vanishes under refinement. 0 (the default) is the paper's undamped scheme.
  double mesh_damping = 0.0;
};

// What lies below the interface x2 = 0 (docs/physics.md "Two solids"): the rigid plane of
// the paper (the default), or a second elastic solid with its own material. For the finite
// elements the lower block has its own height and far (bottom) boundary; the spectral
// boundary-integral method takes it as a half-space x2 < 0.
enum class LowerSide { rigid, elastic };
struct LowerSolid {
  LowerSide side = LowerSide::rigid;
  Material material;                          // the lower solid's (side elastic)
  double height = 20.0;                       // FE: its height below the interface [m]
  bool auto_height = false;                   // FE: "auto", as Geometry::auto_height
  TopBoundary bottom = TopBoundary::traction; // FE: its far boundary at x2 = -height
  bool elastic() const { return side == LowerSide::elastic; }
};

struct SimulationParams {
  Method method = Method::finite_element;
  SpectralOptions spectral;
  FeOptions fe;
  Material material; // the (upper) solid, x2 > 0
  Geometry geometry;
  TopBoundary top = TopBoundary::traction;
  LowerSolid lower; // below the interface: the rigid plane unless a job asks otherwise
  Loading loading;
  Friction friction;
  std::vector<Profile> profiles; // overrides along x1 of loading and friction, in order
  Nucleation nucleation;
  TimeControl time;
  OutputSampling output;
  Probes probes;
  Stations stations;
  int threads = 0;               // 0 = all hardware threads
  ExtraInterfaceLoad extra_load; // empty for every job; used by verification tests
};

} // namespace slipfront
