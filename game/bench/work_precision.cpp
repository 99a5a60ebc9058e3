#include "game/bench/work_precision.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace game::bench {

using namespace phys;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

} // namespace

std::vector<WorkPrecisionPoint> runWorkPrecision(const WorkPrecisionDef& def,
                                                 const std::function<void(int, int)>& progress) {
    std::vector<Integrator> methods = def.integrators;
    if (methods.empty())
        for (const auto& i : integrators()) methods.push_back(i.id);
    const int total = static_cast<int>(methods.size()) * (def.halvings + 1);
    int done = 0;
    std::vector<WorkPrecisionPoint> out;
    for (Integrator m : methods) {
        for (int k = 0; k <= def.halvings; ++k) {
            const double dt = snapDt(def.scene, def.largestDt / std::pow(2.0, k));
            const long steps = stepsFor(def.scene, dt);
            const double seconds = info(def.scene).seconds;
            WorkPrecisionPoint p{def.scene, m, dt, steps, 0.0, 0.0, 0.0};
            std::vector<double> times;
            for (int r = 0; r < std::max(1, def.repeats); ++r) {
                auto w = makeAccuracyWorld(def.scene, m, dt);
                const auto t0 = std::chrono::steady_clock::now();
                for (long i = 0; i < steps; ++i) w->step();
                times.push_back(
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                p.error = accuracyError(def.scene, *w);
            }
            p.cpuSecondsPerSimSecond = median(times) / seconds;
            p.evaluationsPerSimSecond = info(m).evaluations * static_cast<double>(steps) / seconds;
            out.push_back(p);
            if (progress) progress(++done, total);
        }
    }
    return out;
}

double logLogSlope(const std::vector<double>& x, const std::vector<double>& y, double floor) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (!std::isfinite(y[i]) || y[i] <= floor || !(x[i] > 0.0)) continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        ++n;
    }
    if (n < 2) return NAN;
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

double convergenceSlope(const std::vector<WorkPrecisionPoint>& points, Integrator m,
                        double floor) {
    std::vector<double> dt, error;
    for (const auto& p : points)
        if (p.integrator == m) dt.push_back(p.dt), error.push_back(p.error);
    return logLogSlope(dt, error, floor);
}

const WorkPrecisionPoint* cheapestWithin(const std::vector<WorkPrecisionPoint>& points,
                                         double tolerance) {
    const WorkPrecisionPoint* best = nullptr;
    for (const auto& p : points)
        if (std::isfinite(p.error) && p.error <= tolerance &&
            (!best || p.cpuSecondsPerSimSecond < best->cpuSecondsPerSimSecond))
            best = &p;
    return best;
}

std::string toCsv(const std::vector<WorkPrecisionPoint>& points) {
    std::string out = "scene,integrator,dt_s,steps,error_m,cpu_s_per_sim_s,evals_per_sim_s\n";
    char line[256];
    for (const auto& p : points) {
        std::snprintf(line, sizeof line, "%s,%s,%.10g,%ld,%.6g,%.6g,%.6g\n", info(p.scene).name,
                      phys::info(p.integrator).name, p.dt, p.steps, p.error,
                      p.cpuSecondsPerSimSecond, p.evaluationsPerSimSecond);
        out += line;
    }
    return out;
}

} // namespace game::bench
