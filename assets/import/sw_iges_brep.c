/* SPDX-License-Identifier: MIT */
/* The IGES B-rep route (IGES 5.3, 4.147-4.152): 186 manifold solid ->
 * 514 shells -> 510 faces -> 508 loops -> 504 edges (model-space curves)
 * and 502 vertices. A face's orientation is the product of the shell's
 * flag, the face's flag in the shell and any mirroring transform; loops use
 * their parameter-space curves when they have them and compute them from
 * the edges' model-space curves otherwise. */
#include <stdlib.h>
#include <string.h>

#include "sw_iges_internal.h"

/* 504 entry ndx (1-based): its model-space curve. */
static sw_status edge_curve(iges_reader *r, int list, int ndx, int *curve)
{
    if (r->ents[list].type != 504)
        return iges_fail_entity(r, list, SW_ERR_FORMAT, "expected an edge list (504)");
    iges_params p;
    int n;
    sw_status st = iges_params_read(r, list, &p);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 1, "edge count N", 1, 10000000, &n);
    if (st == SW_OK && (ndx < 1 || ndx > n))
        st = iges_fail(r, &p, 1, SW_ERR_FORMAT, "expected an edge index in 1..%d, found %d", n,
                       ndx);
    if (st == SW_OK)
        st = iges_param_entity(r, &p, 2 + 5 * (ndx - 1), "edge curve CURV", 0, curve);
    iges_params_free(&p);
    return st;
}

/* One 508 edge entry from parameter *at: TYPE, EDGE, NDX, OF, K, then K
 * pairs ISOP, CURV. Vertex entries (collapsed edges) add no curve; the
 * loop's gap there is closed in parameter space. */
static sw_status loop_edge(iges_reader *r, const iges_params *p, int *at, iges_face *f,
                           const sw_mat4 *m, iges_loop_build *lb)
{
    int type, list, ndx, of, k, computed = 0;
    sw_status st = iges_param_int(r, p, *at, "edge TYPE", 0, 1, &type);
    if (st == SW_OK)
        st = iges_param_entity(r, p, *at + 1, "edge list EDGE", 0, &list);
    if (st == SW_OK)
        st = iges_param_int(r, p, *at + 2, "edge index NDX", 1, 10000000, &ndx);
    if (st == SW_OK)
        st = iges_param_int(r, p, *at + 3, "orientation OF", 0, 1, &of);
    if (st == SW_OK)
        st = iges_param_int(r, p, *at + 4, "parameter curve count K", 0, 1000000, &k);
    if (st == SW_OK)
        st = iges_param_need(r, p, *at + 5, 2 * k, "ISOP flags and parameter curves");
    if (st != SW_OK || type == 1) {
        *at += 5 + (st == SW_OK ? 2 * k : 0);
        return st;
    }
    iges_curves got = {0};
    for (int i = 0; st == SW_OK && i < k; i++) {
        int pc;
        iges_curves one = {0};
        st = iges_param_entity(r, p, *at + 6 + 2 * i, "parameter curve CURV", 0, &pc);
        if (st == SW_OK)
            st = iges_written_group(r, f, pc, p->entity, &one);
        if (st == SW_OK)
            st = iges_curves_append(r, &got, &one);
        iges_curves_free(&one);
    }
    if (st == SW_ERR_UNSUPPORTED)
        st = SW_OK, iges_curves_free(&got);
    if (st == SW_OK && got.count == 0) {
        int curve;
        st = edge_curve(r, list, ndx, &curve);
        if (st == SW_OK)
            st = iges_computed_group(r, f, curve, m, p->entity, &got);
        computed = 1;
    }
    if (st == SW_OK && !of)
        iges_reverse_group(&got);
    if (st == SW_OK)
        st = iges_loop_take(r, lb, &got, computed);
    iges_curves_free(&got);
    *at += 5 + 2 * k;
    return st;
}

static sw_status read_loop(iges_reader *r, int e, iges_face *f, const sw_mat4 *m, int outer)
{
    if (r->ents[e].type != 508)
        return iges_fail_entity(r, e, SW_ERR_FORMAT, "expected a loop (508)");
    sw_status st = iges_enter(r, e);
    if (st != SW_OK)
        return st;
    iges_params p;
    iges_loop_build lb = {0};
    int n, at = 2;
    st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 1, "edge count N", 1, 10000000, &n);
    for (int i = 0; st == SW_OK && i < n; i++)
        st = loop_edge(r, &p, &at, f, m, &lb);
    if (st == SW_OK && lb.curves.count == 0)
        st = iges_fail(r, &p, 1, SW_ERR_FORMAT, "expected a loop with at least one edge curve");
    st = iges_loop_finish(r, f, &lb, st, outer);
    iges_params_free(&p);
    iges_leave(r, e);
    return st;
}

/* 510: SURF, N, OF (1: the first loop is the outer one), LOOP(1..N). */
static sw_status read_face(iges_reader *r, int e, int flip, iges_faces *out)
{
    if (r->ents[e].type != 510)
        return iges_fail_entity(r, e, SW_ERR_FORMAT, "expected a face (510)");
    sw_status st = iges_enter(r, e);
    if (st != SW_OK)
        return st;
    iges_params p;
    iges_face f = {0};
    int surf, n, of;
    sw_mat4 m;
    st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = iges_param_entity(r, &p, 1, "surface SURF", 0, &surf);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 2, "loop count N", 1, 1000000, &n);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 3, "outer loop flag OF", 0, 1, &of);
    if (st == SW_OK)
        st = iges_param_need(r, &p, 4, n, "loops");
    if (st == SW_OK)
        st = iges_face_surface(r, e, surf, &f, &m);
    f.reversed ^= flip;
    if (st == SW_OK && !of)
        st = iges_face_add_domain_loop(r, &f);
    for (int i = 0; st == SW_OK && i < n; i++) {
        int loop;
        st = iges_param_entity(r, &p, 4 + i, "loop", 0, &loop);
        if (st == SW_OK)
            st = read_loop(r, loop, &f, &m, of && i == 0);
    }
    if (st == SW_OK)
        st = iges_faces_push(r, out, &f);
    r->ents[e].used = 1;
    iges_face_free(&f);
    iges_params_free(&p);
    iges_leave(r, e);
    return st;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* A face listed twice in one shell would be built twice, coincident copies
 * that sewing and the walk then fight over; STEP's shells are held to the
 * same rule (sw_step_scan.c). faces: the shell's n face entities. */
static sw_status check_faces_once(iges_reader *r, int e, const int *faces, int n)
{
    int *sorted = malloc((size_t)(n ? n : 1) * sizeof *sorted);
    if (!sorted)
        return iges_fail_entity(r, e, SW_ERR_NO_MEMORY, "out of memory for a shell of %d faces",
                                n);
    memcpy(sorted, faces, (size_t)n * sizeof *sorted);
    qsort(sorted, (size_t)n, sizeof *sorted, cmp_int);
    int twice = -1;
    for (int i = 1; i < n && twice < 0; i++)
        if (sorted[i] == sorted[i - 1])
            twice = sorted[i];
    free(sorted);
    if (twice < 0)
        return SW_OK;
    int first = 0, again = 0;
    while (faces[first] != twice)
        first++;
    for (again = first + 1; faces[again] != twice; again++)
        ;
    return iges_fail_entity(r, e, SW_ERR_FORMAT, "expected each face once in the shell, found "
                            "the face at D line %d listed again (faces %d and %d of %d)",
                            2 * twice + 1, first + 1, again + 1, n);
}

/* 514: N, then FACE, OF pairs (OF 1: the face's normal is the surface's). */
static sw_status read_shell(iges_reader *r, int e, int flip, iges_faces *out)
{
    if (r->ents[e].type != 514)
        return iges_fail_entity(r, e, SW_ERR_FORMAT, "expected a shell (514)");
    sw_status st = iges_enter(r, e);
    if (st != SW_OK)
        return st;
    iges_params p;
    int n = 0, *faces = NULL, *flags = NULL;
    st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 1, "face count N", 1, IGES_MAX_SHELL_FACES, &n);
    if (st == SW_OK)
        st = iges_param_need(r, &p, 2, 2 * n, "faces and orientation flags");
    if (st == SW_OK && (!(faces = malloc((size_t)n * sizeof *faces)) ||
                        !(flags = malloc((size_t)n * sizeof *flags))))
        st = iges_fail_entity(r, e, SW_ERR_NO_MEMORY, "out of memory for a shell of %d faces", n);
    for (int i = 0; st == SW_OK && i < n; i++) {
        st = iges_param_entity(r, &p, 2 + 2 * i, "face", 0, &faces[i]);
        if (st == SW_OK)
            st = iges_param_int(r, &p, 3 + 2 * i, "orientation flag OF", 0, 1, &flags[i]);
    }
    if (st == SW_OK)
        st = check_faces_once(r, e, faces, n);
    for (int i = 0; st == SW_OK && i < n; i++)
        st = read_face(r, faces[i], flip ^ !flags[i], out);
    free(faces);
    free(flags);
    r->ents[e].used = 1;
    iges_params_free(&p);
    iges_leave(r, e);
    return st;
}

/* 186: SHELL, SOF, N, then VOID, VOF pairs (voids' normals point into them,
 * which their own flags already say). */
static sw_status read_solid(iges_reader *r, int e, iges_faces *out)
{
    sw_status st = iges_enter(r, e);
    if (st != SW_OK)
        return st;
    iges_params p;
    int shell, sof, n = 0;
    st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = iges_param_entity(r, &p, 1, "shell", 0, &shell);
    if (st == SW_OK)
        st = iges_param_int(r, &p, 2, "orientation flag SOF", 0, 1, &sof);
    if (st == SW_OK)
        st = iges_param_int_or(r, &p, 3, "void count N", 0, 1000000, 0, &n);
    if (st == SW_OK)
        st = iges_param_need(r, &p, 4, 2 * n, "void shells and flags");
    if (st == SW_OK)
        st = read_shell(r, shell, !sof, out);
    for (int i = 0; st == SW_OK && i < n; i++) {
        int v, vof;
        st = iges_param_entity(r, &p, 4 + 2 * i, "void shell", 0, &v);
        if (st == SW_OK)
            st = iges_param_int(r, &p, 5 + 2 * i, "void orientation flag", 0, 1, &vof);
        if (st == SW_OK)
            st = read_shell(r, v, !vof, out);
    }
    iges_params_free(&p);
    iges_leave(r, e);
    return st;
}

sw_status iges_read_brep(iges_reader *r, int e, iges_faces *out)
{
    switch (r->ents[e].type) {
    case 186: return read_solid(r, e, out);
    case 514: return read_shell(r, e, 0, out);
    default: return read_face(r, e, 0, out);
    }
}
