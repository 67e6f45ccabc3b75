/* emit.c — the driver of `vigen emit`: the table of emitted variants
 * (variants.def) and the choice of one by name, the passes over working
 * precision until every coefficient rounds, the rendering of the variant's
 * templates with the slots its builder supplies (and the check that each of
 * them is declared by a template), and the loading of a method file for
 * emission. */
#include <stdlib.h>
#include <string.h>
#include "vigen/emit.h"
#include "vigen/method.h"
#include "emit/literals.h"
#include "emit/variant.h"
#include "support/strbuf.h"

static const vigen_emit_variant variants[] = {
#define X(name, description, builder) { name, description, builder },
#include "emit/variants.def"
#undef X
};
enum { NVARIANTS = sizeof variants / sizeof variants[0] };

const vigen_emit_variant *vigen_emit_variant_find(const char *name)
{
    if (name == NULL) return variants;
    for (size_t k = 0; k < NVARIANTS; k++)
        if (strcmp(variants[k].name, name) == 0) return variants + k;
    return NULL;
}

/* The variant and type opt asks for; VIGEN_E_USAGE when there is none of
 * that name, the message listing the variants as variants.def describes
 * them. */
static int check_options(const vigen_emit_variant **variant, const vigen_emit_options *opt, vigen_error *err)
{
    if (vigen_emit_real_name(opt->real) == NULL)
        return vigen_error_set(err, VIGEN_E_USAGE, "unknown real type %d (the types are %s)", opt->real,
                               vigen_emit_real_names());
    if (opt->dim > VIGEN_EMIT_MAX_DIM)
        return vigen_error_set(err, VIGEN_E_USAGE, "static dimension %zu is too large (at most %d; 0 for any)",
                               opt->dim, VIGEN_EMIT_MAX_DIM);
    *variant = vigen_emit_variant_find(opt->variant);
    if (opt->batch && *variant != NULL && (opt->real != VIGEN_REAL_DOUBLE || *variant != variants))
        return vigen_error_set(err, VIGEN_E_USAGE, "--batch is for the %s variant in double precision only "
                               "(leave out --real and --variant, or --batch)", variants[0].name);
    if (*variant != NULL) return VIGEN_OK;
    vigen_strbuf known;
    vigen_strbuf_init(&known);
    vigen_strbuf_append(&known, "");
    for (size_t k = 0; k < NVARIANTS; k++)
        vigen_strbuf_printf(&known, "%s%s (%s)", k ? "; " : "", variants[k].name, variants[k].description);
    vigen_error_set(err, VIGEN_E_USAGE, "unknown variant '%s': the variant%s %s %s", opt->variant,
                    NVARIANTS == 1 ? "" : "s", NVARIANTS == 1 ? "is" : "are", known.data);
    vigen_strbuf_clear(&known);
    return VIGEN_E_USAGE;
}

/* Renders the variant's two templates with the slots, and checks the
 * contract from the builder's side: every slot it supplies is declared by
 * one of the templates (each template checks the rest itself). */
/* Appends the rendering of <dir>/<file> to *text (the batched stepper's
 * templates after the scalar ones: the batch uses the scalar file's
 * helpers). */
static int render_append(char **text, const char *dir, const char *file, const vigen_slots *S,
                         unsigned char *declared, vigen_error *err)
{
    char *path = vigen_strdup_printf("%s/%s", dir, file), *more = NULL;
    int rc = vigen_template_render_file(&more, path, S, declared, err);
    if (rc == VIGEN_OK) {
        char *joined = vigen_strdup_printf("%s\n%s", *text, more);
        free(*text);
        *text = joined;
    }
    free(more);
    free(path);
    return rc;
}

static int render_templates(const vigen_emit_variant *v, const char *top, const vigen_slots *S, int batch,
                            char **h_text, char **c_text, vigen_error *err)
{
    char *dir = top ? vigen_strdup_printf("%s/%s", top, v->name) : vigen_template_dir(v->name);
    char *hp = vigen_strdup_printf("%s/stepper.h.in", dir);
    char *cp = vigen_strdup_printf("%s/stepper.c.in", dir);
    unsigned char *declared = calloc(S->n + 1, 1);
    if (declared == NULL) abort();
    int rc = vigen_template_render_file(h_text, hp, S, declared, err);
    if (rc == VIGEN_OK) rc = vigen_template_render_file(c_text, cp, S, declared, err);
    if (rc == VIGEN_OK && batch) rc = render_append(h_text, dir, "batch.h.in", S, declared, err);
    if (rc == VIGEN_OK && batch) rc = render_append(c_text, dir, "batch.c.in", S, declared, err);
    for (size_t k = 0; rc == VIGEN_OK && k < S->n; k++)
        if (!declared[k])
            rc = vigen_error_set(err, VIGEN_E_TEMPLATE,
                                 "variant %s: its slot builder supplies slot %s, but no template of the variant "
                                 "declares it (%s, %s): use it in a template and declare it there, or stop "
                                 "supplying it", v->name, S->v[k]->name, hp, cp);
    free(declared);
    free(dir);
    free(hp);
    free(cp);
    return rc;
}

/* A splitting of flows the file names (not drift and kick): its flows are
 * the user's, so that it is emitted as the split variant unless another is
 * asked for. */
static int named_flows(const vigen_tableau *t)
{
    if (t->flows == NULL || t->flows->names == NULL) return 0;
    for (slong k = 0; k < t->flows->nflows; k++)
        if (strcmp(t->flows->names[k], k == 0 ? "drift" : "kick") != 0) return 1;
    return t->flows->nflows != 2;
}

const char *vigen_emit_variant_chosen(const vigen_tableau *t, const char *variant)
{
    if (variant != NULL) return variant;
    return named_flows(t) ? "split" : variants[0].name;
}

int vigen_emit_render(const vigen_tableau *t, const vigen_emit_options *opt, char **h_text, char **c_text,
                      char **ident, vigen_error *err)
{
    *h_text = *c_text = NULL;
    *ident = NULL;
    const vigen_emit_variant *variant;
    int rc = check_options(&variant, opt, err);
    if (rc != VIGEN_OK) return rc;
    if (opt->variant == NULL && named_flows(t)) variant = vigen_emit_variant_find("split");
    if (t->flows != NULL && t->flows->nstep > 0 && strcmp(variant->name, "split") != 0)
        return vigen_error_set(err, VIGEN_E_USAGE, "'%s' has bracket flows, which only the split variant emits (the "
                               "flows as the user's functions)", t->name ? t->name : "unnamed");
    char *id = vigen_emit_identifier(opt->name ? opt->name : "stepper");
    emit_ctx E;
    memset(&E, 0, sizeof E);
    E.t = t;
    E.s = t->s;
    E.real = opt->real;
    E.allow_inexact = opt->allow_inexact;
    E.bits = vigen_emit_reals[opt->real].bits;
    E.variant = variant == variants ? NULL : variant->name;
    E.err = err;
    E.At_text = t->has_At ? t->At_text : t->A_text;
    E.bt_text = t->has_bt ? t->bt_text : t->b_text;
    E.c = _arb_vec_init(t->s);
    E.b = _arb_vec_init(t->s);
    E.bt = _arb_vec_init(t->s);
    arb_mat_init(E.A, t->s, t->s);
    arb_mat_init(E.At, t->s, t->s);
    E.marks = calloc((size_t)vigen_emit_n_entries(t->s), 1);
    if (E.marks == NULL) abort();
    vigen_slots slots;
    vigen_slots_init(&slots);
    for (E.prec = E.bits + 64;; E.prec *= 2) {
        rc = vigen_emit_evaluate(&E, err);
        if (rc != VIGEN_OK) break;
        vigen_slots_clear(&slots);
        memset(E.marks, 0, (size_t)vigen_emit_n_entries(t->s));
        E.inexact_derived = 0;
        E.fail_kind = 0;
        rc = variant->build(&slots, &E, opt, id);
        if (rc != VIGEN_E_PRECISION) break;
        if (E.prec >= 8192) {
            /* more precision does not help: entries given as rounded decimals */
            if (!opt->allow_inexact || E.inexact_done) break;
            E.inexact_done = 1;
            E.prec /= 2;
        }
        vigen_error_clear(err);
    }
    if (rc == VIGEN_E_PRECISION && E.fail_kind) {
        vigen_emit_precision_message(&E, opt, err);
        rc = err->code;
    }
    if (rc == VIGEN_OK) rc = render_templates(variant, opt->template_dir, &slots, opt->batch, h_text, c_text, err);
    if (rc == VIGEN_OK) vigen_emit_report_marks(&E, opt);
    vigen_slots_clear(&slots);
    free(E.marks);
    _arb_vec_clear(E.c, t->s);
    _arb_vec_clear(E.b, t->s);
    _arb_vec_clear(E.bt, t->s);
    arb_mat_clear(E.A);
    arb_mat_clear(E.At);
    if (rc != VIGEN_OK) {
        free(*h_text);
        free(*c_text);
        *h_text = *c_text = NULL;
        free(id);
        return rc;
    }
    *ident = id;
    return VIGEN_OK;
}

/* A spec is generated again with twice the digits while a value still
 * cannot be rounded (it lies that close to a rounding boundary), up to 960
 * digits; --allow-inexact applies only at the last attempt, so that it never
 * stands in for digits the generator could still certify. */
int vigen_emit_load_render(vigen_tableau *t, int *loaded, const char *file, vigen_emit_options *opt, char **h,
                           char **c, char **ident, vigen_error *err)
{
    *loaded = 0;
    /* a wrong option is found before the file is read or a spec generated */
    const vigen_emit_variant *variant;
    int rc = check_options(&variant, opt, err);
    if (rc != VIGEN_OK) return rc;
    vigen_method *m = NULL;
    rc = vigen_method_load(&m, file, NULL, err);
    if (rc != VIGEN_OK) return rc;
    int generated = vigen_method_is_generated(m);
    int inexact = opt->allow_inexact;
    const slong max_digits = 960;
    for (slong digits = vigen_emit_spec_digits(opt->real);; digits *= 2) {
        if (*loaded) vigen_tableau_clear(t);
        *loaded = 0;
        rc = vigen_method_tableau(t, m, digits, err); /* its messages name the file */
        if (rc != VIGEN_OK) break;
        *loaded = 1;
        int last = !generated || digits * 2 > max_digits;
        opt->allow_inexact = last ? inexact : 0;
        rc = vigen_emit_render(t, opt, h, c, ident, err);
        if (rc != VIGEN_E_INEXACT || last) break;
        vigen_error_clear(err);
    }
    opt->allow_inexact = inexact;
    vigen_method_free(m);
    if (rc != VIGEN_OK && *loaded) {
        /* the rendering's messages name entries of the tableau, not the file
         * (a template error is about the installation, not the file) */
        if (rc != VIGEN_E_TEMPLATE && err->message) vigen_error_prefix(err, "%s: ", file);
        vigen_tableau_clear(t);
        *loaded = 0;
    }
    return rc;
}
