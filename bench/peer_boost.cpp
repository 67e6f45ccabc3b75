// peer_boost.cpp — Boost.Odeint's symplectic_rkn_sb3a_mclachlan (McLachlan
// 1995, the method of tableaux/published/mclachlan_rkn_4.lua) on one problem
// of the collection, for bench/peer_bench.c to set beside the emitted
// stepper of the same method.  State: std::array of the problem's dimension
// (Boost's array algebra, loops of a length the compiler knows); the force is
// the problem's own (peer_boost_force, compiled from bench/peer_bench.c with
// PEER_FORCE_ONLY and linked with -flto, so that it is inlined here as in
// the emitted direct-force stepper), counted by the functor.  Built by
// bench/peer_run.sh with the same problem macros as peer_bench.c.
//   peer_boost [STEPS [OUT_FILE]]     STEPS 0: PEER_STEPS
// Writes to OUT_FILE (default stdout): "ns_per_step forces_per_step
// relative_energy_error steps" (the fastest of 5 runs of STEPS steps from the
// problem's initial state), then in hexadecimal (exact) q and p after those
// steps and q and p after one step from the initial state.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <boost/numeric/odeint.hpp>
#include <vigen/problems.h>

extern "C" void peer_boost_force(double t, const double *q, double *f, void *ctx);

namespace {

typedef std::array<double, PEER_DIM> vec;

unsigned long forces;

// dp/dt = f(q) = -dV/dq
struct momentum_rhs {
    void *ctx;
    void operator()(const vec &q, vec &dpdt) const
    {
        forces++;
        peer_boost_force(0.0, q.data(), dpdt.data(), ctx);
    }
};

// dq/dt = M^-1 p (the problems of unit mass use Boost's own dq/dt = p)
struct coordinate_rhs {
    vec inv_mass;
    void operator()(const vec &p, vec &dqdt) const
    {
        for (std::size_t k = 0; k < PEER_DIM; k++) dqdt[k] = inv_mass[k] * p[k];
    }
};

}  // namespace

int main(int argc, char **argv)
{
    long steps = argc > 1 ? std::atol(argv[1]) : 0;
    if (steps <= 0) steps = PEER_STEPS;
    vigen_problem *pb;
    char why[256] = "not of dimension PEER_DIM";
    if (vigen_problem_create(&pb, PEER_NAME, PEER_PARAMS, why, sizeof why) != VIGEN_SUCCESS ||
        vigen_problem_dim(pb) != PEER_DIM) {
        std::fprintf(stderr, "peer_boost: %s: %s\n", PEER_NAME, why);
        return 1;
    }
    const double h = PEER_H;
    momentum_rhs force{ pb };
    coordinate_rhs velocity;
    vec e{}, v{};
    for (std::size_t k = 0; k < PEER_DIM; k++) {   // diag(M^-1) from dH/dp of unit momenta
        e[k] = 1;
        vigen_problem_hamiltonian(pb)->dHdp(0, e.data(), e.data(), v.data(), pb);
        velocity.inv_mass[k] = v[k];
        e[k] = 0;
    }
    boost::numeric::odeint::symplectic_rkn_sb3a_mclachlan<vec> stepper;
    auto step = [&](vec &q, vec &p, double t) {
#if PEER_UNIT_MASS
        stepper.do_step(force, std::make_pair(std::ref(q), std::ref(p)), t, h);
#else
        stepper.do_step(std::make_pair(velocity, force), std::make_pair(std::ref(q), std::ref(p)), t, h);
#endif
    };
    vec q, p, q1, p1;
    double t = 0, best = 1e300;
    unsigned long evals = 0;
    for (int run = 0; run < 5; run++) {
        vigen_problem_initial(pb, &t, q.data(), p.data());
        forces = 0;
        auto t0 = std::chrono::steady_clock::now();
        for (long k = 0; k < steps; k++) {
            step(q, p, t);
            t += h;
        }
        std::chrono::duration<double> el = std::chrono::steady_clock::now() - t0;
        if (el.count() < best) best = el.count();
        evals = forces;
    }
    double t1;
    vigen_problem_initial(pb, &t1, q1.data(), p1.data());
    step(q1, p1, t1);
    double t0, q0[PEER_DIM], p0[PEER_DIM];
    vigen_problem_initial(pb, &t0, q0, p0);
    double H0 = vigen_problem_energy(pb, t0, q0, p0);
    double err = std::fabs((vigen_problem_energy(pb, t, q.data(), p.data()) - H0) / H0);
    std::FILE *out = argc > 2 ? std::fopen(argv[2], "w") : stdout;
    if (out == nullptr) {
        std::fprintf(stderr, "peer_boost: cannot write %s\n", argv[2]);
        return 1;
    }
    std::fprintf(out, "%.6g %.6g %.6g %ld\n", 1e9 * best / (double)steps, (double)evals / (double)steps, err, steps);
    for (const vec *x : { &q, &p, &q1, &p1 })
        for (std::size_t k = 0; k < PEER_DIM; k++) std::fprintf(out, "%a\n", (*x)[k]);
    if (out != stdout && std::fclose(out) != 0) {
        std::fprintf(stderr, "peer_boost: cannot write %s\n", argv[2]);
        return 1;
    }
    vigen_problem_free(pb);
    return 0;
}
