// SPDX-License-Identifier: Apache-2.0
// lutkit match on a 1080p source and a 1080p reference, to a 33^3 LUT (issue 23: under 1 s on
// both cores), against a plain HM-MKL-HM written here the way a numpy script does it (sort,
// unique values and counts, linear interpolation of the distribution functions, the MKL matrix
// from eigen-decompositions; float64, one thread), the library's figure beside the C++ written
// the numpy way; bench/compare_numpy.sh runs numpy itself (bench/match_numpy.py) against the whole
// command. The pictures: the sample scene scaled to 1920x1080 with a
// fine deterministic grain (a screenshot has more than the sample's 1730 colours), and the same
// picture graded by a formula (channel mix, curves, saturation), flipped and shuffled.
// Run: build/bin/lutkit_bench --benchmark_filter=Match
// Counters: mean_steps and p99_steps, the LUT applied to the source against the true grade.
#include "TestPaths.h"
#include "lut/Image.h"
#include "lut/formats/ImageIO.h"
#include "lut/match/LutQuality.h"
#include "lut/match/Match.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <time.h>
#include <vector>

namespace {

double q8(double v) {
    return std::round(std::clamp(v, 0.0, 1.0) * 255.0) / 255.0;
}

void grade(const double in[3], double out[3]) {
    const double m[3][3] = {{0.86, 0.10, 0.04}, {0.06, 0.84, 0.10}, {0.02, 0.14, 0.84}};
    double x[3], c[3];
    for (int i = 0; i < 3; ++i)
        x[i] = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2];
    c[0] = 0.04 + 0.96 * std::pow(std::max(x[0], 0.0), 0.85);
    c[1] = 0.5 + 0.5 * std::tanh(2.4 * (x[1] - 0.5)) / std::tanh(1.2);
    c[2] = 0.92 * x[2] + 0.02;
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    for (int i = 0; i < 3; ++i)
        out[i] = luma + 1.25 * (c[i] - luma);
}

struct Pictures {
    lut::Image source, truth, reference;
};

const Pictures& pictures() {
    static const Pictures p = [] {
        const lut::Image small =
            lut::formats::readImage(std::string(LUTKIT_SAMPLES_DIR) + "/sample_scene.png").image;
        const int w = 1920, h = 1080;
        Pictures out;
        out.source = lut::Image(w, h, 1.0f);
        out.truth = lut::Image(w, h, 1.0f);
        std::uint64_t state = 12345;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double sx = (x + 0.5) * small.width() / w - 0.5;
                const double sy = (y + 0.5) * small.height() / h - 0.5;
                const int x0 = std::clamp(static_cast<int>(std::floor(sx)), 0, small.width() - 2);
                const int y0 = std::clamp(static_cast<int>(std::floor(sy)), 0, small.height() - 2);
                const double fx = std::clamp(sx - x0, 0.0, 1.0), fy = std::clamp(sy - y0, 0.0, 1.0);
                double v[3], g[3];
                for (int c = 0; c < 3; ++c) {
                    state = state * 6364136223846793005ull + 1442695040888963407ull;
                    const double grain =
                        (static_cast<double>(state >> 40) / 16777216.0 - 0.5) * 3.0;
                    const double a =
                        small.pixel(x0, y0)[c] * (1 - fx) + small.pixel(x0 + 1, y0)[c] * fx;
                    const double b =
                        small.pixel(x0, y0 + 1)[c] * (1 - fx) + small.pixel(x0 + 1, y0 + 1)[c] * fx;
                    v[c] = q8(a * (1 - fy) + b * fy + grain / 255.0);
                    out.source.pixel(x, y)[c] = static_cast<float>(v[c]);
                }
                grade(v, g);
                for (int c = 0; c < 3; ++c)
                    out.truth.pixel(x, y)[c] = static_cast<float>(q8(g[c]));
            }
        std::vector<std::size_t> order(static_cast<std::size_t>(w) * h);
        std::iota(order.begin(), order.end(), 0);
        std::shuffle(order.begin(), order.end(), std::mt19937(7));
        out.reference = lut::Image(w, h, 1.0f);
        for (std::size_t i = 0; i < order.size(); ++i)
            for (int c = 0; c < 3; ++c)
                out.reference.data()[4 * i + c] =
                    out.truth.data()[4 * (order.size() - 1 - order[i]) + c];
        return out;
    }();
    return p;
}

// ---- the plain HM-MKL-HM (float64, one thread) ----

using Column = std::vector<double>;

// np.unique(x, return_counts) -> cumulative -> np.interp: each value of `src` moved to the
// reference value at its quantile.
Column matchColumn(const Column& src, const Column& ref) {
    auto cdf = [](const Column& v, Column& values, Column& quantiles) {
        Column s = v;
        std::sort(s.begin(), s.end());
        values.clear();
        quantiles.clear();
        for (std::size_t i = 0; i < s.size();) {
            std::size_t j = i;
            while (j < s.size() && s[j] == s[i])
                ++j;
            values.push_back(s[i]);
            quantiles.push_back(static_cast<double>(j) / static_cast<double>(s.size()));
            i = j;
        }
    };
    Column sv, sq, rv, rq;
    cdf(src, sv, sq);
    cdf(ref, rv, rq);
    auto interp = [](double x, const Column& xs, const Column& ys) {
        if (x <= xs.front())
            return ys.front();
        if (x >= xs.back())
            return ys.back();
        const std::size_t k =
            static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
        const double t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
        return ys[k - 1] + t * (ys[k] - ys[k - 1]);
    };
    Column out(src.size());
    for (std::size_t i = 0; i < src.size(); ++i)
        out[i] = interp(interp(src[i], sv, sq), rq, rv);
    return out;
}

using Mat = std::array<std::array<double, 3>, 3>;

Mat multiply(const Mat& a, const Mat& b) {
    Mat c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                c[i][j] += a[i][k] * b[k][j];
    return c;
}

// Symmetric matrix function by cyclic Jacobi (what np.linalg.eigh gives).
Mat matrixFunction(Mat a, double (*f)(double)) {
    Mat v{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 50; ++sweep)
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::fabs(a[p][q]) < 1e-300)
                    continue;
                const double th = 0.5 * std::atan2(2 * a[p][q], a[q][q] - a[p][p]);
                const double c = std::cos(th), s = std::sin(th);
                for (int k = 0; k < 3; ++k) {
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    Mat out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                out[i][j] += v[i][k] * f(a[k][k]) * v[j][k];
    return out;
}

void plainHmMklHm(const lut::Image& srcImg, const lut::Image& refImg, std::vector<double>& out) {
    const std::size_t n = static_cast<std::size_t>(srcImg.width()) * srcImg.height();
    const std::size_t m = static_cast<std::size_t>(refImg.width()) * refImg.height();
    std::array<Column, 3> s, r;
    for (int c = 0; c < 3; ++c) {
        s[c].resize(n);
        r[c].resize(m);
        for (std::size_t i = 0; i < n; ++i)
            s[c][i] = srcImg.data()[4 * i + c];
        for (std::size_t i = 0; i < m; ++i)
            r[c][i] = refImg.data()[4 * i + c];
        s[c] = matchColumn(s[c], r[c]);
    }
    auto moments = [](const std::array<Column, 3>& x, std::array<double, 3>& mean, Mat& cov) {
        const double n = static_cast<double>(x[0].size());
        for (int i = 0; i < 3; ++i)
            mean[i] = std::accumulate(x[i].begin(), x[i].end(), 0.0) / n;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                double acc = 0;
                for (std::size_t k = 0; k < x[0].size(); ++k)
                    acc += (x[i][k] - mean[i]) * (x[j][k] - mean[j]);
                cov[i][j] = acc / n;
            }
    };
    std::array<double, 3> mu, mv;
    Mat su, sv;
    moments(s, mu, su);
    moments(r, mv, sv);
    const Mat suHalf = matrixFunction(su, [](double l) { return std::sqrt(std::max(l, 1e-12)); });
    const Mat suInv =
        matrixFunction(su, [](double l) { return 1 / std::sqrt(std::max(l, 1e-12)); });
    const Mat t = multiply(
        multiply(suInv, matrixFunction(multiply(multiply(suHalf, sv), suHalf),
                                       [](double l) { return std::sqrt(std::max(l, 0.0)); })),
        suInv);
    std::array<Column, 3> z;
    for (int c = 0; c < 3; ++c) {
        z[c].resize(n);
        for (std::size_t k = 0; k < n; ++k)
            z[c][k] = mv[c] + t[c][0] * (s[0][k] - mu[0]) + t[c][1] * (s[1][k] - mu[1]) +
                      t[c][2] * (s[2][k] - mu[2]);
    }
    out.resize(3 * n);
    for (int c = 0; c < 3; ++c) {
        const Column y = matchColumn(z[c], r[c]);
        for (std::size_t k = 0; k < n; ++k)
            out[3 * k + c] = y[k];
    }
}

double processSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void errorCounters(benchmark::State& state, const std::vector<double>& result) {
    const lut::Image& truth = pictures().truth;
    std::vector<double> d(result.size());
    for (std::size_t i = 0; i < result.size(); ++i)
        d[i] = std::fabs(q8(result[i]) - truth.data()[4 * (i / 3) + i % 3]) * 255.0;
    double mean = std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
    std::sort(d.begin(), d.end());
    state.counters["mean_steps"] = mean;
    state.counters["p99_steps"] =
        d[static_cast<std::size_t>(0.99 * static_cast<double>(d.size() - 1))];
}

void BM_MatchLut(benchmark::State& state, lut::MatchMethod method) {
    const Pictures& p = pictures();
    lut::MatchPicture src, ref;
    src.pixels = p.source.view();
    src.bitDepth = 8;
    src.name = "source";
    ref.pixels = p.reference.view();
    ref.bitDepth = 8;
    ref.name = "reference";
    lut::MatchOptions o;
    o.method = method;
    o.nthreads = static_cast<int>(state.range(0));
    lut::MatchResult r;
    double cpu = 0.0;
    for (auto _ : state) {
        const double c0 = processSeconds();
        r = lut::matchLook(src, {ref}, o);
        cpu += processSeconds() - c0;
        benchmark::DoNotOptimize(r.lut.cube->data());
    }
    // CPU time of every thread: what the run costs on a machine busy with other work
    state.counters["cpu_s"] = cpu / static_cast<double>(state.iterations());
    state.counters["fit_s"] = r.report.secondsFit;
    state.counters["lut_s"] = r.report.secondsBake;
    state.counters["measure_s"] = r.report.secondsMeasure;
    lut::Image applied = p.source;
    lut::LutFileSampler(r.lut).applyPixels(applied.data(), applied.pixels().size() / 4);
    std::vector<double> result(applied.pixels().size() / 4 * 3);
    for (std::size_t i = 0; i < result.size(); ++i)
        result[i] = applied.data()[4 * (i / 3) + i % 3];
    errorCounters(state, result);
}

void BM_MatchPlainHmMklHm(benchmark::State& state) {
    const Pictures& p = pictures();
    std::vector<double> out;
    double cpu = 0.0;
    for (auto _ : state) {
        const double c0 = processSeconds();
        plainHmMklHm(p.source, p.reference, out);
        cpu += processSeconds() - c0;
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["cpu_s"] = cpu / static_cast<double>(state.iterations());
    errorCounters(state, out);
}

} // namespace

BENCHMARK_CAPTURE(BM_MatchLut, HmMklHm, lut::MatchMethod::HmMklHm)
    ->Arg(2)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_MatchLut, Auto, lut::MatchMethod::Auto)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_MatchPlainHmMklHm)->Unit(benchmark::kMillisecond)->UseRealTime();
