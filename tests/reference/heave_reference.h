// Linear potential flow (Newman, "Marine Hydrodynamics", 1977, ch. 4 and 6; Faltinsen, "Sea Loads
// on Ships and Offshore Structures", 1990, ch. 3) around a box floating in the middle of a closed
// tank: the reference a floating body's heave is compared against. It holds the water the box
// sets moving (its added mass), the waves it makes and their reflections off the tank's walls,
// exactly for that tank, to the grid's resolution.
//
// The water is a velocity potential φ (∇²φ = 0) on a grid of cubic cells, finite volumes, in the
// quarter of the tank that heave's two mirror symmetries leave:
//   floor, walls, mirror planes, the box's sides   ∂φ/∂n = 0
//   the box's bottom                              ∂φ/∂z = W, the box's heave velocity
//   the free surface                              φ = φ_s, given (a face half a cell above its cell)
// φ is linear in φ_s and W, so one solve per surface face and one for W give the maps
//   η̇ = G φ_s + s W            the surface's rise (G: the Dirichlet-to-Neumann map)
//   ∫_bottom φ dA = b·φ_s + a W
// and the surface (p = 0: φ̇_s = −g η) and the box (its weight against the pressure −ρ φ̇ − ρ g z
// on its bottom) move as
//   φ̇_s = −g η,   (m + ρ a) Ẇ = −ρ g A_w Z + ρ g b·η,   Ż = W
// with m, A_w and a those of the quarter. ρ a is the added mass at infinite frequency (the surface
// held at φ = 0); the waves make the rest.
#pragma once

#include <cstddef>
#include <vector>

namespace tidepool::test {

struct HeaveTank {
  double length = 0, width = 0;        // the tank's floor, along x and y, m
  double depth = 0;                    // of the still water, m
  double boxLength = 0, boxWidth = 0;  // the box's, along x and y, centred (0: no box), m
  double draft = 0;                    // the box's bottom under the still water, m
  double mass = 0;                     // the box's, kg
  double rho = 1000, g = 9.81;
};

class HeaveReference {
 public:
  // Cells of `cell` m: the halves of the tank's and the box's sides, the depth and the draft must
  // be whole cells (throws std::invalid_argument).
  HeaveReference(const HeaveTank& tank, double cell);

  double addedMass() const { return 4.0 * m_tank.rho * m_a; }  // at infinite frequency, kg
  std::size_t surfaceFaces() const { return m_faces.size(); }
  double surfaceX(std::size_t f) const;  // the centre of surface face f, m (in the quarter x < length/2)

  struct State {
    std::vector<double> eta, phi;  // per surface face: elevation (m), potential (m²/s)
    double z = 0, w = 0;           // the box's heave (m) and its velocity (m/s)
  };
  State rest() const;  // still water, the box at its draft
  // At rest with the box pushed down by a steady force to z < 0: the water it displaces raises
  // the free surface evenly (the state the force leaves once the motion has died out).
  State pushed(double z) const;
  // Symplectic Euler, φ_s and W first: `steps` steps of dt.
  void advance(State& s, double dt, int steps) const;

 private:
  double waterplane() const { return 0.25 * m_tank.boxLength * m_tank.boxWidth; }  // the quarter's A_w, m²

  HeaveTank m_tank;
  double m_cell = 0;
  std::vector<std::size_t> m_faces;  // per surface face, its cell column (i ny + j)
  std::size_t m_ny = 0;
  std::vector<std::vector<double>> m_G;  // m_G[f][k]: the rise at face f for a unit φ_s at face k
  std::vector<double> m_s, m_b;
  double m_a = 0;
};

// A trace's turning points: the times of its lowest and highest values in turn, the first one a
// lowest, each counted once the trace has come back more than `hysteresis` from it.
std::vector<double> turningPoints(const std::vector<double>& trace, double dt, double hysteresis);

}  // namespace tidepool::test
