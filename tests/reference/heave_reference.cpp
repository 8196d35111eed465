#include "reference/heave_reference.h"

#include <cmath>
#include <stdexcept>

namespace tidepool::test {

namespace {

int cells(double length, double cell) {
  const double n = length / cell;
  if (n < -1e-9 || std::abs(n - std::round(n)) > 1e-4) throw std::invalid_argument("heave reference: not whole cells");
  return int(std::round(n));
}

// A symmetric positive definite matrix with entries only within `band` of the diagonal, factored
// as L Lᵀ (Cholesky), its lower band stored row by row: low[i][d] is L(i, i − d).
class BandCholesky {
 public:
  BandCholesky(std::size_t n, std::size_t band) : m_band(band), m_low(n, std::vector<double>(band + 1, 0.0)) {}
  double& at(std::size_t i, std::size_t j) { return m_low[i][i - j]; }  // j ≤ i, before factor()
  void factor() {
    const std::size_t n = m_low.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t first = i > m_band ? i - m_band : 0;
      for (std::size_t j = first; j <= i; ++j) {
        double sum = m_low[i][i - j];
        for (std::size_t k = std::max(first, j > m_band ? j - m_band : 0); k < j; ++k)
          sum -= m_low[i][i - k] * m_low[j][j - k];
        m_low[i][i - j] = i == j ? std::sqrt(sum) : sum / m_low[j][0];
      }
    }
  }
  std::vector<double> solve(std::vector<double> x) const {
    const std::size_t n = m_low.size();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t d = 1; d <= std::min(m_band, i); ++d) x[i] -= m_low[i][d] * x[i - d];
      x[i] /= m_low[i][0];
    }
    for (std::size_t i = n; i-- > 0;) {
      x[i] /= m_low[i][0];
      for (std::size_t d = 1; d <= std::min(m_band, i); ++d) x[i - d] -= m_low[i][d] * x[i];
    }
    return x;
  }

 private:
  std::size_t m_band;
  std::vector<std::vector<double>> m_low;
};

}  // namespace

HeaveReference::HeaveReference(const HeaveTank& tank, double cell) : m_tank(tank), m_cell(cell) {
  const int nx = cells(tank.length / 2, cell), ny = cells(tank.width / 2, cell), nz = cells(tank.depth, cell);
  const int bx = cells(tank.boxLength / 2, cell), by = cells(tank.boxWidth / 2, cell);
  const int nd = bx > 0 ? cells(tank.draft, cell) : 0;
  if (bx > nx || by > ny || nd >= nz) throw std::invalid_argument("heave reference: the box does not fit");
  m_ny = std::size_t(ny);
  // The quarter x < length/2, y < width/2; the box in its corner at the mirror planes.
  auto box = [&](int i, int j, int k) { return bx > 0 && i >= nx - bx && j >= ny - by && k >= nz - nd; };
  auto index = [&](int i, int j, int k) { return (std::size_t(i) * ny + j) * nz + k; };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      if (!box(i, j, nz - 1)) m_faces.push_back(std::size_t(i) * ny + j);

  // Σ over a cell's faces of (φ_cell − φ_beyond), a surface face counting twice (half a cell
  // away), equals h times the velocity the box's bottom pushes in.
  BandCholesky matrix(std::size_t(nx) * ny * nz, std::size_t(ny) * nz);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const std::size_t c = index(i, j, k);
        if (box(i, j, k)) {
          matrix.at(c, c) = 1.0;
          continue;
        }
        double diagonal = 0.0;
        const int around[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                                  {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
        for (const auto& n : around) {
          if (n[0] < 0 || n[0] >= nx || n[1] < 0 || n[1] >= ny || n[2] < 0) continue;  // a wall or a mirror
          if (n[2] >= nz) {
            diagonal += 2.0;  // the surface
            continue;
          }
          if (box(n[0], n[1], n[2])) continue;  // the box's side, or its bottom (the right-hand side)
          diagonal += 1.0;
          const std::size_t m = index(n[0], n[1], n[2]);
          if (m < c) matrix.at(c, m) = -1.0;
        }
        matrix.at(c, c) = diagonal;
      }
  matrix.factor();

  // One solve per surface face's unit potential, and one for W = 1.
  const std::size_t faces = m_faces.size();
  const std::size_t columns = std::size_t(nx) * ny;
  auto top = [&](std::size_t column) { return column * nz + std::size_t(nz - 1); };
  std::vector<std::size_t> under;  // the cells under the box's bottom
  for (int i = nx - bx; i < nx && nd > 0; ++i)
    for (int j = ny - by; j < ny; ++j) under.push_back(index(i, j, nz - nd - 1));
  auto solve = [&](std::size_t unitFace, double w, std::vector<double>& rise, double& bottom) {
    std::vector<double> rhs(columns * nz, 0.0);
    if (unitFace < faces) rhs[top(m_faces[unitFace])] = 2.0;
    for (std::size_t c : under) rhs[c] += w * cell;
    const std::vector<double> phi = matrix.solve(rhs);
    rise.assign(faces, 0.0);
    for (std::size_t f = 0; f < faces; ++f) rise[f] = 2.0 * ((f == unitFace ? 1.0 : 0.0) - phi[top(m_faces[f])]) / cell;
    bottom = 0.0;
    for (std::size_t c : under) bottom += (phi[c] + 0.5 * w * cell) * cell * cell;
  };
  m_G.assign(faces, std::vector<double>(faces, 0.0));
  m_b.assign(faces, 0.0);
  std::vector<double> rise;
  for (std::size_t k = 0; k < faces; ++k) {
    solve(k, 0.0, rise, m_b[k]);
    for (std::size_t f = 0; f < faces; ++f) m_G[f][k] = rise[f];
  }
  if (nd > 0)
    solve(faces, 1.0, m_s, m_a);
  else
    m_s.assign(faces, 0.0);
}

double HeaveReference::surfaceX(std::size_t f) const { return (double(m_faces[f] / m_ny) + 0.5) * m_cell; }

HeaveReference::State HeaveReference::rest() const {
  State s;
  s.eta.assign(m_faces.size(), 0.0);
  s.phi.assign(m_faces.size(), 0.0);
  return s;
}

HeaveReference::State HeaveReference::pushed(double z) const {
  State s = rest();
  const double free = double(m_faces.size()) * m_cell * m_cell;
  s.z = z;
  s.eta.assign(m_faces.size(), -z * waterplane() / free);
  return s;
}

void HeaveReference::advance(State& s, double dt, int steps) const {
  const HeaveTank& t = m_tank;
  const std::size_t faces = m_faces.size();
  const bool hasBox = t.boxLength > 0.0 && t.draft > 0.0;
  std::vector<double> rise(faces);
  for (int n = 0; n < steps; ++n) {
    if (hasBox) {  // the quarter's share of the box
      double lift = -t.rho * t.g * waterplane() * s.z;
      for (std::size_t k = 0; k < faces; ++k) lift += t.rho * t.g * m_b[k] * s.eta[k];
      s.w += dt * lift / (0.25 * t.mass + t.rho * m_a);
    }
    for (std::size_t k = 0; k < faces; ++k) s.phi[k] -= dt * t.g * s.eta[k];
    for (std::size_t f = 0; f < faces; ++f) {
      double r = m_s[f] * s.w;
      for (std::size_t k = 0; k < faces; ++k) r += m_G[f][k] * s.phi[k];
      rise[f] = r;
    }
    for (std::size_t f = 0; f < faces; ++f) s.eta[f] += dt * rise[f];
    s.z += dt * s.w;
  }
}

std::vector<double> turningPoints(const std::vector<double>& trace, double dt, double hysteresis) {
  std::vector<double> out;
  bool down = true;
  std::size_t best = 0;
  for (std::size_t i = 1; i < trace.size(); ++i) {
    if (down ? trace[i] < trace[best] : trace[i] > trace[best]) best = i;
    if (down ? trace[i] > trace[best] + hysteresis : trace[i] < trace[best] - hysteresis) {
      out.push_back(double(best) * dt);
      down = !down;
      best = i;
    }
  }
  return out;
}

}  // namespace tidepool::test
