/* basis.c — basis functions: the families of basis.def, Lagrange
 * polynomials, expressions and Lua functions, with their values and rigorous
 * integrals. */
#include <stdlib.h>
#include <string.h>
#include <acb_calc.h>
#include <arb_poly.h>
#include <flint/fmpz_poly.h>
#include "method/basis.h"
#include "method/families.h"
#include "vigen/limits.h"
#include "support/strbuf.h"

enum { FN_POLY, FN_TRIG, FN_EXPR, FN_LUA };

typedef struct {
    int kind;
    char *label;
    arb_poly_t poly, antideriv;   /* FN_POLY */
    slong k;                      /* FN_TRIG: frequency (0 = constant) */
    int is_cos;                   /* FN_TRIG */
    vigen_expr *expr;             /* FN_EXPR (borrowed from the spec) */
    slong index;                  /* FN_LUA: index into spec->items */
} basis_fn;

struct vigen_basis {
    vigen_spec *spec;
    slong count;
    int interpolating;
    basis_fn *fns;
};

slong vigen_basis_count(const vigen_basis *basis) { return basis->count; }
int vigen_basis_is_interpolating(const vigen_basis *basis) { return basis->interpolating; }
const char *vigen_basis_label(const vigen_basis *basis, slong i) { return basis->fns[i].label; }

static void set_poly(basis_fn *f, const arb_poly_t p, slong prec)
{
    f->kind = FN_POLY;
    arb_poly_set(f->poly, p);
    arb_poly_integral(f->antideriv, f->poly, prec); /* constant term 0: int_0^x */
}

static void set_poly_fmpz(basis_fn *f, const fmpz_poly_t p, slong prec)
{
    arb_poly_t q;
    arb_poly_init(q);
    arb_poly_set_fmpz_poly(q, p, prec);
    set_poly(f, q, prec);
    arb_poly_clear(q);
}

/* Shifted Legendre P_k(2t - 1) = sum_j (-1)^(k+j) C(k,j) C(k+j,j) t^j (integer coefficients). */
static void shifted_legendre(fmpz_poly_t p, slong k)
{
    fmpz_t c, d;
    fmpz_init(c);
    fmpz_init(d);
    fmpz_poly_zero(p);
    for (slong j = 0; j <= k; j++) {
        fmpz_bin_uiui(c, (ulong)k, (ulong)j);
        fmpz_bin_uiui(d, (ulong)(k + j), (ulong)j);
        fmpz_mul(c, c, d);
        if ((k + j) % 2) fmpz_neg(c, c);
        fmpz_poly_set_coeff_fmpz(p, j, c);
    }
    fmpz_clear(c);
    fmpz_clear(d);
}

/* Shifted Chebyshev T_k(2t - 1) by the three-term recurrence. */
static void shifted_chebyshev_t(fmpz_poly_t p, slong k)
{
    fmpz_poly_t t0, t1, x2, tmp;
    fmpz_poly_init(t0); fmpz_poly_init(t1); fmpz_poly_init(x2); fmpz_poly_init(tmp);
    fmpz_poly_set_si(t0, 1);
    fmpz_poly_set_coeff_si(t1, 0, -1);
    fmpz_poly_set_coeff_si(t1, 1, 2);        /* 2t - 1 */
    fmpz_poly_scalar_mul_si(x2, t1, 2);      /* 2(2t - 1) */
    if (k == 0) fmpz_poly_set(p, t0);
    else {
        for (slong j = 1; j < k; j++) {
            fmpz_poly_mul(tmp, x2, t1);
            fmpz_poly_sub(tmp, tmp, t0);
            fmpz_poly_swap(t0, t1);
            fmpz_poly_swap(t1, tmp);
        }
        fmpz_poly_set(p, t1);
    }
    fmpz_poly_clear(t0); fmpz_poly_clear(t1); fmpz_poly_clear(x2); fmpz_poly_clear(tmp);
}

/* ---- the families of basis.def: psi_{i+1} of each, 0-based i ---------- */

static void basis_monomial(basis_fn *f, fmpz_poly_t p, slong i, slong prec)
{
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, i, 1);
    set_poly_fmpz(f, p, prec);
    f->label = i == 0 ? vigen_strdup("1") : i == 1 ? vigen_strdup("t") : vigen_strdup_printf("t^%ld", (long)i);
}

static void basis_legendre(basis_fn *f, fmpz_poly_t p, slong i, slong prec)
{
    shifted_legendre(p, i);
    set_poly_fmpz(f, p, prec);
    f->label = vigen_strdup_printf("P_%ld(2t-1)", (long)i);
}

static void basis_chebyshev_t(basis_fn *f, fmpz_poly_t p, slong i, slong prec)
{
    shifted_chebyshev_t(p, i);
    set_poly_fmpz(f, p, prec);
    f->label = vigen_strdup_printf("T_%ld(2t-1)", (long)i);
}

/* 1, cos(pi t), sin(pi t), cos(2 pi t), sin(2 pi t), ... */
static void basis_trig(basis_fn *f, fmpz_poly_t p, slong i, slong prec)
{
    (void)p;
    (void)prec;
    f->kind = FN_TRIG;
    f->k = (i + 1) / 2;
    f->is_cos = (i == 0) || (i % 2 == 1);
    if (i == 0) f->label = vigen_strdup("1");
    else if (f->k == 1) f->label = vigen_strdup(f->is_cos ? "cos(pi*t)" : "sin(pi*t)");
    else f->label = vigen_strdup_printf("%s(%ld*pi*t)", f->is_cos ? "cos" : "sin", (long)f->k);
}

typedef void (*basis_family_fn)(basis_fn *f, fmpz_poly_t p, slong i, slong prec);

static const struct {
    const char *name;
    basis_family_fn fn;
} basis_families[] = {
#define X(name, fn, description) { #name, fn },
#include "method/basis.def"
#undef X
};

#define BASIS_NUM_FAMILIES ((slong)(sizeof(basis_families) / sizeof(basis_families[0])))

static basis_family_fn basis_lookup(const char *name)
{
    for (slong k = 0; name != NULL && k < BASIS_NUM_FAMILIES; k++)
        if (strcmp(basis_families[k].name, name) == 0) return basis_families[k].fn;
    return NULL;
}

static int init_family(vigen_basis *B, const char *family, slong prec, vigen_error *err)
{
    basis_family_fn fn = basis_lookup(family);
    if (fn == NULL) {
        vigen_strbuf known;
        vigen_strbuf_init(&known);
        for (slong k = 0; k < BASIS_NUM_FAMILIES; k++)
            vigen_strbuf_printf(&known, "%s%s", k ? ", " : "", basis_families[k].name);
        int rc = vigen_error_set(err, VIGEN_E_SPEC, "unknown basis family '%s' (known: %s)",
                                 family ? family : "(none)", known.data);
        vigen_strbuf_clear(&known);
        return rc;
    }
    fmpz_poly_t p;
    fmpz_poly_init(p);
    for (slong i = 0; i < B->count; i++) fn(&B->fns[i], p, i, prec);
    fmpz_poly_clear(p);
    return VIGEN_OK;
}

/* Lagrange polynomials l_j(t) = prod_{k != j} (t - c_k)/(c_j - c_k). */
static int init_lagrange(vigen_basis *B, arb_srcptr nodes, slong prec, vigen_error *err)
{
    slong s = B->count;
    arb_poly_t p, lin;
    arb_t den, diff;
    arb_poly_init(p); arb_poly_init(lin);
    arb_init(den); arb_init(diff);
    int rc = VIGEN_OK;
    for (slong j = 0; j < s && rc == VIGEN_OK; j++) {
        arb_poly_one(p);
        arb_one(den);
        for (slong k = 0; k < s; k++) {
            if (k == j) continue;
            arb_poly_fit_length(lin, 2);
            arb_neg(lin->coeffs, nodes + k);
            arb_one(lin->coeffs + 1);
            _arb_poly_set_length(lin, 2);
            arb_poly_mul(p, p, lin, prec);
            arb_sub(diff, nodes + j, nodes + k, prec);
            arb_mul(den, den, diff, prec);
        }
        if (arb_contains_zero(den)) {
            rc = vigen_error_set(err, VIGEN_E_PRECISION, "nodes %ld and another one cannot be told apart", (long)(j + 1));
            break;
        }
        arb_poly_scalar_div(p, p, den, prec);
        set_poly(&B->fns[j], p, prec);
        B->fns[j].label = vigen_strdup_printf("l_%ld (Lagrange polynomial at node %ld)", (long)(j + 1), (long)(j + 1));
    }
    arb_poly_clear(p); arb_poly_clear(lin);
    arb_clear(den); arb_clear(diff);
    return rc;
}

int vigen_basis_new(vigen_basis **out, vigen_spec *spec, arb_srcptr nodes, slong prec, vigen_error *err)
{
    vigen_basis *B = calloc(1, sizeof(*B));
    if (B == NULL) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    B->spec = spec;
    B->count = spec->basis_count;
    B->fns = calloc((size_t)B->count, sizeof(basis_fn));
    for (slong i = 0; i < B->count; i++) {
        arb_poly_init(B->fns[i].poly);
        arb_poly_init(B->fns[i].antideriv);
    }
    int rc = VIGEN_OK;
    if (spec->basis_kind == VIGEN_SPEC_BASIS_LAGRANGE) {
        B->interpolating = 1;
        rc = init_lagrange(B, nodes, prec, err);
    } else if (spec->basis_kind == VIGEN_SPEC_BASIS_FAMILY) {
        rc = init_family(B, spec->basis_family, prec, err);
    } else {
        arb_poly_t p;
        arb_poly_init(p);
        for (slong i = 0; i < B->count; i++) {
            vigen_spec_basis_item *item = &spec->items[i];
            basis_fn *f = &B->fns[i];
            f->label = vigen_strdup(item->label);
            if (item->kind == VIGEN_SPEC_ITEM_EXPR) {
                if (vigen_expr_to_arb_poly(p, item->expr, prec)) set_poly(f, p, prec);
                else { f->kind = FN_EXPR; f->expr = item->expr; }
            } else {
                f->kind = FN_LUA;
                f->index = i;
            }
        }
        arb_poly_clear(p);
    }
    if (rc != VIGEN_OK) { vigen_basis_free(B); return rc; }
    *out = B;
    return VIGEN_OK;
}

void vigen_basis_free(vigen_basis *B)
{
    if (B == NULL) return;
    for (slong i = 0; i < B->count; i++) {
        arb_poly_clear(B->fns[i].poly);
        arb_poly_clear(B->fns[i].antideriv);
        free(B->fns[i].label);
    }
    free(B->fns);
    free(B);
}

/* A complex ball that should be real: accept it when the imaginary part is
 * exactly zero, ask for more precision when it merely contains zero. */
static int real_part_checked(arb_t res, const acb_t z, const char *label, const char *what, vigen_error *err)
{
    if (!acb_is_finite(z))
        return vigen_error_set(err, VIGEN_E_PRECISION, "%s of %s is not finite at this precision", what, label);
    if (!arb_contains_zero(acb_imagref(z))) {
        char *im = arb_get_str(acb_imagref(z), 10, 0);
        int code = vigen_error_set(err, VIGEN_E_DOMAIN, "%s of %s is complex (imaginary part %s); basis functions "
                                   "must be real on [0, 1]", what, label, im);
        flint_free(im);
        return code;
    }
    arb_set(res, acb_realref(z));
    return VIGEN_OK;
}

int vigen_basis_value(arb_t res, vigen_basis *B, slong i, const arb_t x, slong prec, vigen_error *err)
{
    basis_fn *f = &B->fns[i];
    int rc = VIGEN_OK;
    switch (f->kind) {
    case FN_POLY:
        arb_poly_evaluate(res, f->poly, x, prec);
        break;
    case FN_TRIG: {
        if (f->k == 0) { arb_one(res); break; }
        arb_t kx, sn, cs;
        arb_init(kx); arb_init(sn); arb_init(cs);
        arb_mul_si(kx, x, f->k, prec);
        arb_sin_cos_pi(sn, cs, kx, prec);
        arb_set(res, f->is_cos ? cs : sn);
        arb_clear(kx); arb_clear(sn); arb_clear(cs);
        break;
    }
    case FN_EXPR:
        rc = vigen_expr_eval_arb(res, f->expr, x, prec, err);
        break;
    case FN_LUA: {
        acb_t z, t;
        acb_init(z); acb_init(t);
        acb_set_arb(t, x);
        rc = vigen_spec_call_basis(z, B->spec, f->index, t, 0, prec, err);
        if (rc == VIGEN_OK) {
            if (!arb_is_zero(acb_imagref(z)) && arb_contains_zero(acb_imagref(z)))
                rc = vigen_error_set(err, VIGEN_E_PRECISION, "value of %s not certainly real", f->label);
            else rc = real_part_checked(res, z, f->label, "the value", err);
        }
        acb_clear(z); acb_clear(t);
        break;
    }
    }
    if (rc == VIGEN_OK && !arb_is_finite(res)) {
        char *xs = arb_get_str(x, 20, 0);
        rc = vigen_error_set(err, VIGEN_E_DOMAIN, "%s is not finite at t = %s", f->label, xs);
        flint_free(xs);
    }
    return rc;
}

typedef struct {
    vigen_basis *basis;
    basis_fn *fn;
    int failed;
    vigen_error err;
} integrand_ctx;

/* The budget of integrand evaluations of one certified quadrature: ample for
 * the analytic basis functions it is meant for (a few thousand suffice at
 * hundreds of digits); a function it cannot certify within it is reported.
 * Fuzzing builds use a smaller budget (and Gauss-Legendre rules of at most 64
 * points, whose nodes cost much at high precision), so that the fuzzer
 * spends its time on new inputs rather than on one integrand that will not
 * converge: the code path is the same. */
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
enum { QUADRATURE_EVALS_PER_BIT = 8, QUADRATURE_EVALS_BASE = 2000, QUADRATURE_DEG_LIMIT = 64 };
#else
enum { QUADRATURE_EVALS_PER_BIT = 200, QUADRATURE_EVALS_BASE = 100000, QUADRATURE_DEG_LIMIT = 0 /* arb's default */ };
#endif

/* acb_calc_integrate integrand: order 1 asks for a holomorphy check. */
static int integrand(acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
    integrand_ctx *ctx = param;
    if (order > 1) flint_abort(); /* acb_calc_integrate never asks for more */
    if (ctx->failed) { acb_indeterminate(res); return 0; }
    int analytic = (order == 1);
    if (ctx->fn->kind == FN_EXPR) {
        vigen_expr_eval_acb(res, ctx->fn->expr, z, analytic, prec);
    } else {
        vigen_error e;
        vigen_error_init(&e);
        if (vigen_spec_call_basis(res, ctx->basis->spec, ctx->fn->index, z, analytic, prec, &e) != VIGEN_OK) {
            ctx->failed = 1;
            ctx->err = e;
            acb_indeterminate(res);
            return 0;
        }
        vigen_error_clear(&e);
    }
    return 0;
}

int vigen_basis_integral(arb_t res, vigen_basis *B, slong i, const arb_t x, slong prec, vigen_error *err)
{
    basis_fn *f = &B->fns[i];
    if (arb_is_zero(x)) { arb_zero(res); return VIGEN_OK; }
    switch (f->kind) {
    case FN_POLY:
        arb_poly_evaluate(res, f->antideriv, x, prec);
        return VIGEN_OK;
    case FN_TRIG: {
        if (f->k == 0) { arb_set(res, x); return VIGEN_OK; }
        /* int_0^x cos(k pi t) = sin(k pi x)/(k pi); int_0^x sin(k pi t) = (1 - cos(k pi x))/(k pi) */
        arb_t kx, sn, cs, kpi;
        arb_init(kx); arb_init(sn); arb_init(cs); arb_init(kpi);
        arb_mul_si(kx, x, f->k, prec);
        arb_sin_cos_pi(sn, cs, kx, prec);
        arb_const_pi(kpi, prec);
        arb_mul_si(kpi, kpi, f->k, prec);
        if (f->is_cos) arb_div(res, sn, kpi, prec);
        else {
            arb_sub_si(cs, cs, 1, prec);
            arb_neg(cs, cs);
            arb_div(res, cs, kpi, prec);
        }
        arb_clear(kx); arb_clear(sn); arb_clear(cs); arb_clear(kpi);
        return VIGEN_OK;
    }
    default: {
        /* sin, cos, exp of linear arguments (cos(pi*t), exp(t/2), ...): the
         * exact antiderivative, much faster than quadrature at high precision */
        if (f->kind == FN_EXPR && vigen_expr_integral_closed_form(res, f->expr, x, prec)) return VIGEN_OK;
        /* quadrature costs about the cube of the precision: its own share of the cap */
        if (prec > vigen_prec_limit() / VIGEN_QUADRATURE_PREC_SHARE)
            return vigen_error_set(err, VIGEN_E_LIMIT, "the integral of %s needs quadrature at %ld bits, above its "
                                   "cap of %ld bits (1/%d of --max-prec BITS, which raises it; or ask for fewer "
                                   "--digits, or use basis functions with closed-form integrals)", f->label,
                                   (long)prec, vigen_prec_limit() / VIGEN_QUADRATURE_PREC_SHARE,
                                   VIGEN_QUADRATURE_PREC_SHARE);
        integrand_ctx ctx;
        ctx.basis = B;
        ctx.fn = f;
        ctx.failed = 0;
        vigen_error_init(&ctx.err);
        acb_t r, a, b;
        acb_init(r); acb_init(a); acb_init(b);
        acb_set_arb(b, x);
        mag_t tol;
        mag_init(tol);
        mag_set_ui_2exp_si(tol, 1, -prec);
        acb_calc_integrate_opt_t opt;
        acb_calc_integrate_opt_init(opt);
        opt->eval_limit = QUADRATURE_EVALS_PER_BIT * prec + QUADRATURE_EVALS_BASE;
        if (QUADRATURE_DEG_LIMIT > 0) opt->deg_limit = QUADRATURE_DEG_LIMIT;   /* the Gauss-Legendre degree */
        int status = acb_calc_integrate(r, integrand, &ctx, a, b, prec, tol, opt, prec);
        int rc = VIGEN_OK;
        if (ctx.failed) {
            rc = ctx.err.code;
            vigen_error_set(err, rc, "%s", ctx.err.message ? ctx.err.message : "basis function failed");
            vigen_error_clear(&ctx.err);
        } else if (status != ARB_CALC_SUCCESS || !acb_is_finite(r)) {
            char *xs = arb_get_str(x, 10, 0);
            rc = vigen_error_set(err, VIGEN_E_INTEGRAL, "the integral of %s from 0 to %s could not be certified",
                                 f->label, xs);
            flint_free(xs);
        } else {
            rc = real_part_checked(res, r, f->label, "the integral", err);
        }
        mag_clear(tol);
        acb_clear(r); acb_clear(a); acb_clear(b);
        return rc;
    }
    }
}
