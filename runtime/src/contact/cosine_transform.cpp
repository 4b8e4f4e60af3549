#include "cosine_transform.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace wavecontact::detail {

namespace {

std::mutex& planner_mutex() {  // FFTW's planner is not reentrant; its plans' execution is
  static std::mutex m;
  return m;
}

}  // namespace

CosineTransform::CosineTransform(std::size_t points, Kind kind) : data_(points) {
  const std::lock_guard<std::mutex> lock(planner_mutex());
  if (kind == Kind::dct1) {
    if (points < 2) throw std::logic_error("CosineTransform: a DCT-I of fewer than 2 points");
    const std::size_t N = points - 1;
    extension_ = fftw_alloc_real(2 * N);
    spectrum_ = fftw_alloc_complex(N + 1);
    plan_ = extension_ && spectrum_
                ? fftw_plan_dft_r2c_1d(static_cast<int>(2 * N), extension_, spectrum_, FFTW_ESTIMATE)
                : nullptr;
  } else {
    plan_ = fftw_plan_r2r_1d(static_cast<int>(points), data_.data(), data_.data(),
                             kind == Kind::dct2 ? FFTW_REDFT10 : FFTW_REDFT01, FFTW_ESTIMATE);
  }
  if (plan_ == nullptr) {
    fftw_free(extension_);
    fftw_free(spectrum_);
    throw std::runtime_error("wavecontact: FFTW could not plan a cosine transform");
  }
}

CosineTransform::~CosineTransform() {
  const std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_destroy_plan(plan_);
  fftw_free(extension_);
  fftw_free(spectrum_);
}

void CosineTransform::apply() {
  if (extension_ == nullptr) {
    fftw_execute(plan_);
    return;
  }
  // x_0 .. x_N, then x_{N-1} .. x_1: the period 2N of the even sequence; its transform is real.
  const std::size_t N = data_.size() - 1;
  std::copy(data_.begin(), data_.end(), extension_);
  std::reverse_copy(data_.begin() + 1, data_.end() - 1, extension_ + N + 1);
  fftw_execute(plan_);
  for (std::size_t k = 0; k <= N; ++k) data_[k] = spectrum_[k][0];
}

CosineTransform& planned_transform(std::size_t points, CosineTransform::Kind kind) {
  constexpr std::size_t kept_plans = 64;
  thread_local std::map<std::pair<std::size_t, CosineTransform::Kind>, std::unique_ptr<CosineTransform>> transforms;
  const auto key = std::make_pair(points, kind);
  if (transforms.size() >= kept_plans && transforms.count(key) == 0) transforms.clear();
  std::unique_ptr<CosineTransform>& transform = transforms[key];
  if (!transform) transform = std::make_unique<CosineTransform>(points, kind);
  return *transform;
}

std::vector<double> cosine_series_on_grid(const std::vector<double>& c, std::size_t N) {
  if (c.size() > N + 1) throw std::logic_error("cosine_series_on_grid: more terms than grid points");
  CosineTransform& t = planned_transform(N + 1, CosineTransform::Kind::dct1);
  std::vector<double>& x = t.data();
  std::fill(x.begin(), x.end(), 0.0);
  // y_k = x_0 + (-1)^k x_N + 2 sum x_j cos(pi j k / N): the inner terms halved.
  for (std::size_t j = 0; j < c.size(); ++j) x[j] = j == 0 || j == N ? c[j] : c[j] / 2;
  t.apply();
  return x;
}

}  // namespace wavecontact::detail
