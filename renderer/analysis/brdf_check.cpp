#include "analysis/brdf_check.h"

#include "models/model_spec.h"
#include "numeric/angles.h"
#include "reference/classic.h"

#include <algorithm>
#include <cmath>

namespace m3055 {

namespace {
using numeric::kPi;

dvec3 spherical(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}
}  // namespace

std::vector<dvec3> check_directions(int n_theta, int n_phi) {
    std::vector<dvec3> out{dvec3(0, 0, 1)};
    for (int t = 1; t <= n_theta; ++t)
        for (int p = 0; p < n_phi; ++p) {
            dvec3 d = spherical(0.5 * kPi * t / n_theta, 2.0 * kPi * (p + 0.25) / n_phi);
            if (t == n_theta) d.z = 0.0;  // exactly grazing
            out.push_back(d);
        }
    return out;
}

GridStats grid_stats(const std::vector<float>& f, const std::vector<dvec3>& dirs) {
    GridStats s;
    const std::size_t n = dirs.size();
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t c = 0; c < 3; ++c) {
                const double a = f[(j * n + i) * 3 + c];
                if (!(dirs[j].z > 0.0)) {  // exactly grazing view: reported apart
                    if (!std::isfinite(a)) ++s.grazing_nonfinite;
                    continue;
                }
                ++s.values;
                const bool bad = !std::isfinite(a) || a < 0.0;
                if (bad && s.first_bad < 0) s.first_bad = long(j * n + i);
                if (!std::isfinite(a)) {
                    ++s.nonfinite;
                    continue;
                }
                if (a < 0.0) ++s.negative;
                s.max_value = std::max(s.max_value, a);
                if (!(dirs[i].z > 0.0 && dirs[j].z > 0.0) || i >= j) continue;
                const double b = f[(i * n + j) * 3 + c];
                const double scale = std::max(std::abs(a), std::abs(b));
                if (std::isfinite(b) && scale > 1e-6) s.max_reciprocity = std::max(s.max_reciprocity, std::abs(a - b) / scale);
            }
    return s;
}

void merge(GridStats& a, const GridStats& b, long setting) {
    if (a.first_bad < 0 && b.first_bad >= 0) a.first_bad = b.first_bad, a.first_setting = setting;
    a.grazing_nonfinite += b.grazing_nonfinite;
    a.nonfinite += b.nonfinite;
    a.negative += b.negative;
    a.values += b.values;
    a.max_value = std::max(a.max_value, b.max_value);
    a.max_reciprocity = std::max(a.max_reciprocity, b.max_reciprocity);
}

AlbedoSamples albedo_samples(int n_mu, int n_phi) {
    AlbedoSamples s;
    const double dmu = 1.0 / n_mu, dphi = 2.0 * kPi / n_phi;
    for (int m = 0; m < n_mu; ++m) {
        const double mu = (m + 0.5) * dmu;
        for (int p = 0; p < n_phi; ++p) {
            s.L.push_back(spherical(std::acos(mu), (p + 0.5) * dphi));
            s.weight.push_back(mu * dmu * dphi);
        }
    }
    return s;
}

std::vector<dvec3> view_directions(const std::vector<double>& degrees) {
    std::vector<dvec3> out;
    for (double d : degrees) out.push_back(spherical(d * kPi / 180.0, 0.0));
    return out;
}

std::vector<double> directional_albedo(const std::vector<float>& f, const AlbedoSamples& samples, std::size_t views) {
    const std::size_t n = samples.L.size();
    std::vector<double> out;
    for (std::size_t j = 0; j < views; ++j) {
        double best = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            double sum = 0;
            for (std::size_t i = 0; i < n; ++i) sum += double(f[(j * n + i) * 3 + c]) * samples.weight[i];
            best = c == 0 ? sum : std::max(best, sum);
        }
        out.push_back(best);
    }
    return out;
}

std::optional<DistributionIntegral> distribution_integral(const Material& material) {
    if (material.model().name != "microfacet") return std::nullopt;
    const auto distribution = static_cast<ref::Distribution>(material.choice("distribution"));
    DistributionIntegral out;
    // Simpson's rule in theta_h on [0, pi/2], 20000 intervals (the narrowest
    // lobe, m = 0.001, spans ~50 of them).
    const int n = 20000;
    const double h = 0.5 * kPi / n;
    for (const Lobe& lobe : material.lobes()) {
        double sum = 0;
        for (int k = 0; k <= n; ++k) {
            const double t = k * h, cos_t = std::cos(t);
            const double D = ref::microfacet_D(distribution, lobe.m, cos_t, t);
            sum += (k == 0 || k == n ? 1 : k % 2 ? 4 : 2) * D * cos_t * std::sin(t);
        }
        out.integral += lobe.w * 2.0 * kPi * sum * h / 3.0;
        out.weights += lobe.w;
    }
    return out;
}

}  // namespace m3055
