/* SPDX-License-Identifier: MIT */
/* IGES trimmed surfaces: 144 (surface, outer boundary or the natural one,
 * inner boundaries, each a 142 curve on surface), 143 bounded surface with
 * its 141 boundaries, and bare surfaces as untrimmed faces. A boundary's
 * parameter-space curve is used when there is one and the preference flag
 * does not say the model-space curve is the better one; otherwise it is
 * computed from the model-space curve (sw_pcurve). */
#include <stdlib.h>
#include <string.h>

#include "sw_iges_internal.h"

/* 142: CRTN, SPTR, BPTR, CPTR, PREF (IGES 5.3, 4.22). */
static sw_status read_curve_on_surface(iges_reader *r, int e, iges_face *f, const sw_mat4 *outer,
                                       iges_loop_build *lb)
{
    if (r->ents[e].type != 142)
        return iges_fail_entity(r, e, SW_ERR_FORMAT,
                                "expected a curve on a parametric surface (142) as a boundary");
    sw_status st = iges_enter(r, e);
    if (st != SW_OK)
        return st;
    iges_params p;
    int b = -1, c = -1, pref = 0, computed = 0;
    iges_curves got = {0};
    sw_mat4 m = sw_mat4_identity(), both;
    st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = iges_param_entity(r, &p, 3, "parameter-space curve BPTR", 1, &b);
    if (st == SW_OK)
        st = iges_param_entity(r, &p, 4, "model-space curve CPTR", 1, &c);
    if (st == SW_OK)
        st = iges_param_int_or(r, &p, 5, "preference PREF", 0, 3, 0, &pref);
    if (st == SW_OK && b >= 0 && (pref != 2 || c < 0)) {
        st = iges_written_group(r, f, b, e, &got);
        if (st == SW_ERR_UNSUPPORTED && c >= 0)
            st = SW_OK;   /* the model-space curve will do */
    }
    if (st == SW_OK && got.count > 0 && c >= 0) {
        st = iges_entity_matrix(r, e, &m);
        both = sw_mat4_mul(outer, &m);
        if (st == SW_OK)
            st = iges_measure_gap(r, f, c, &both, &got);
    } else if (st == SW_OK && got.count == 0) {
        if (c < 0)
            st = iges_fail(r, &p, 3, SW_ERR_FORMAT,
                           "expected a parameter-space curve (BPTR) or a model-space curve "
                           "(CPTR), found neither");
        if (st == SW_OK)
            st = iges_entity_matrix(r, e, &m);
        both = sw_mat4_mul(outer, &m);
        if (st == SW_OK)
            st = iges_computed_group(r, f, c, &both, e, &got);
        computed = 1;
    }
    if (st == SW_OK)
        st = iges_loop_take(r, lb, &got, computed);
    iges_curves_free(&got);
    iges_params_free(&p);
    iges_leave(r, e);
    return st;
}

/* The face's surface with the owner's transform; the normal flips with it. */
sw_status iges_face_surface(iges_reader *r, int owner, int surface, iges_face *f,
                              sw_mat4 *m)
{
    memset(f, 0, sizeof *f);
    f->entity = owner;
    sw_status st = iges_entity_matrix(r, owner, m);
    if (st == SW_OK)
        st = iges_read_surface(r, surface, &f->surface);
    if (st == SW_OK) {
        iges_surface_transform(&f->surface, m);
        f->reversed = f->surface.flipped;
        r->ents[surface].used = 1;
    }
    return st;
}

/* 144: PTS, N1, N2, PTO, PTI(1..N2) (IGES 5.3, 4.34). */
static sw_status trimmed_params(iges_reader *r, const iges_params *p, iges_face *f,
                                iges_faces *out)
{
    int pts, n1, n2, pto;
    sw_mat4 m;
    sw_status st = iges_param_entity(r, p, 1, "surface PTS", 0, &pts);
    if (st == SW_OK)
        st = iges_param_int(r, p, 2, "outer boundary flag N1", 0, 1, &n1);
    if (st == SW_OK)
        st = iges_param_int(r, p, 3, "inner boundary count N2", 0, 1000000, &n2);
    if (st == SW_OK)
        st = iges_param_entity(r, p, 4, "outer boundary PTO", !n1, &pto);
    if (st == SW_OK)
        st = iges_param_need(r, p, 5, n2, "inner boundaries");
    if (st == SW_OK)
        st = iges_face_surface(r, p->entity, pts, f, &m);
    iges_loop_build lb = {0};
    if (st == SW_OK && n1) {
        st = read_curve_on_surface(r, pto, f, &m, &lb);
        st = iges_loop_finish(r, f, &lb, st, 1);
    } else if (st == SW_OK && n2 > 0) {
        st = iges_face_add_domain_loop(r, f);
    }
    for (int i = 0; st == SW_OK && i < n2; i++) {
        int pti;
        st = iges_param_entity(r, p, 5 + i, "inner boundary PTI", 0, &pti);
        if (st == SW_OK)
            st = read_curve_on_surface(r, pti, f, &m, &lb);
        st = iges_loop_finish(r, f, &lb, st, 0);
    }
    if (st == SW_OK)
        st = iges_faces_push(r, out, f);
    return st;
}

sw_status iges_read_trimmed(iges_reader *r, int e, iges_faces *out)
{
    sw_status st = iges_enter(r, e);
    if (st != SW_OK)
        return st;
    iges_params p;
    iges_face f = {0};
    st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = trimmed_params(r, &p, &f, out);
    iges_face_free(&f);
    iges_params_free(&p);
    iges_leave(r, e);
    return st;
}

/* One 141 curve entry: CRVPT, SENSE, K, PSCPT(1..K), from parameter at. */
static sw_status boundary_curve(iges_reader *r, const iges_params *p, int *at, int type,
                                int pref, iges_face *f, const sw_mat4 *outer, iges_loop_build *lb)
{
    int crv, sense, k, computed = 0;
    sw_status st = iges_param_entity(r, p, *at, "model-space curve CRVPT", 0, &crv);
    if (st == SW_OK)
        st = iges_param_int(r, p, *at + 1, "orientation SENSE", 1, 2, &sense);
    if (st == SW_OK)
        st = iges_param_int(r, p, *at + 2, "parameter curve count K", 0, 1000000, &k);
    if (st == SW_OK)
        st = iges_param_need(r, p, *at + 3, k, "parameter-space curves");
    iges_curves got = {0};
    if (st == SW_OK && type == 1 && pref != 2 && k > 0) {
        for (int i = 0; st == SW_OK && i < k; i++) {
            int pc;
            iges_curves one = {0};
            st = iges_param_entity(r, p, *at + 3 + i, "parameter-space curve", 0, &pc);
            if (st == SW_OK)
                st = iges_written_group(r, f, pc, p->entity, &one);
            if (st == SW_OK)
                st = iges_curves_append(r, &got, &one);
            iges_curves_free(&one);
        }
        if (st == SW_ERR_UNSUPPORTED)
            st = SW_OK, iges_curves_free(&got);
    }
    sw_mat4 m = sw_mat4_identity(), both;
    if (st == SW_OK)
        st = iges_entity_matrix(r, p->entity, &m);
    both = sw_mat4_mul(outer, &m);
    if (st == SW_OK && got.count > 0) {
        st = iges_measure_gap(r, f, crv, &both, &got);
    } else if (st == SW_OK && got.count == 0) {
        st = iges_computed_group(r, f, crv, &both, p->entity, &got);
        computed = 1;
    }
    if (st == SW_OK && sense == 2)
        iges_reverse_group(&got);
    if (st == SW_OK)
        st = iges_loop_take(r, lb, &got, computed);
    iges_curves_free(&got);
    *at += 3 + k;
    return st;
}

/* 141: TYPE, PREF, SPTR, N, then N curve entries (IGES 5.3, 4.31). */
static sw_status read_boundary(iges_reader *r, int e, iges_face *f, const sw_mat4 *outer,
                               int outer_loop)
{
    if (r->ents[e].type != 141)
        return iges_fail_entity(r, e, SW_ERR_FORMAT, "expected a boundary (141)");
    sw_status st = iges_enter(r, e);
    if (st != SW_OK)
        return st;
    iges_params p;
    int type = 0, pref = 0, n = 0, at = 5;
    iges_loop_build lb = {0};
    st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 1, "boundary type TYPE", 0, 1, &type);
    if (st == SW_OK)
        st = iges_param_int_or(r, &p, 2, "preference PREF", 0, 3, 0, &pref);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 4, "curve count N", 1, 1000000, &n);
    for (int i = 0; st == SW_OK && i < n; i++)
        st = boundary_curve(r, &p, &at, type, pref, f, outer, &lb);
    st = iges_loop_finish(r, f, &lb, st, outer_loop);
    iges_params_free(&p);
    iges_leave(r, e);
    return st;
}

/* 143: BTYPE, SPTR, N, BDPT(1..N); the first boundary is the outer one. */
sw_status iges_read_bounded(iges_reader *r, int e, iges_faces *out)
{
    sw_status st = iges_enter(r, e);
    if (st != SW_OK)
        return st;
    iges_params p;
    iges_face f = {0};
    int sptr, n;
    sw_mat4 m;
    st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = iges_param_entity(r, &p, 2, "surface SPTR", 0, &sptr);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 3, "boundary count N", 1, 1000000, &n);
    if (st == SW_OK)
        st = iges_param_need(r, &p, 4, n, "boundaries");
    if (st == SW_OK)
        st = iges_face_surface(r, e, sptr, &f, &m);
    for (int i = 0; st == SW_OK && i < n; i++) {
        int b;
        st = iges_param_entity(r, &p, 4 + i, "boundary", 0, &b);
        if (st == SW_OK)
            st = read_boundary(r, b, &f, &m, i == 0);
    }
    if (st == SW_OK)
        st = iges_faces_push(r, out, &f);
    iges_face_free(&f);
    iges_params_free(&p);
    iges_leave(r, e);
    return st;
}

sw_status iges_read_untrimmed(iges_reader *r, int e, iges_faces *out)
{
    iges_face f = {0};
    f.entity = e;
    sw_status st = iges_read_surface(r, e, &f.surface);
    if (st == SW_OK) {
        f.reversed = f.surface.flipped;
        st = iges_faces_push(r, out, &f);
    }
    iges_face_free(&f);
    return st;
}
