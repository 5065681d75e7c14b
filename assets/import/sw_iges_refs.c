/* SPDX-License-Identifier: MIT */
/* Entity references in the native IGES reader: the guards every entity
 * read goes through (cycles, depth, total expansion), the one error for
 * an unsupported type, and 124 transformation chains. Below the readers of
 * curves, surfaces and faces, which all call it; calls nothing above. */
#include "sw_iges_internal.h"

sw_status iges_enter(iges_reader *r, int e)
{
    if (r->ents[e].busy)
        return iges_fail_entity(r, e, SW_ERR_FORMAT,
                                "expected entity references without cycles, found one back to "
                                "this entity");
    if (r->depth >= IGES_MAX_DEPTH)
        return iges_fail_entity(r, e, SW_ERR_FORMAT,
                                "expected entity references nested at most %d deep",
                                IGES_MAX_DEPTH);
    if (++r->visits > (long)IGES_VISITS_PER_ENTITY * r->ent_count + 1000)
        return iges_fail_entity(r, e, SW_ERR_FORMAT,
                                "expected each entity to be referenced a few times, found "
                                "references that expand to more than %ld entities",
                                (long)IGES_VISITS_PER_ENTITY * r->ent_count + 1000);
    r->ents[e].busy = 1;
    r->depth++;
    return SW_OK;
}

void iges_leave(iges_reader *r, int e)
{
    r->ents[e].busy = 0;
    r->depth--;
}

sw_status iges_unsupported(iges_reader *r, int e, const char *expected)
{
    r->unsupported_type = r->ents[e].type;
    return iges_fail_entity(r, e, SW_ERR_UNSUPPORTED, "expected %s, found entity type %d, "
                            "which this reader does not support", expected, r->ents[e].type);
}

/* 124: R11 R12 R13 T1 R21 R22 R23 T2 R31 R32 R33 T3 (IGES 5.3, 4.21). */
static sw_status read_matrix(iges_reader *r, int e, sw_mat4 *out)
{
    iges_params p;
    double v[12];
    sw_status st = iges_params_read(r, e, &p);
    if (st == SW_OK)
        st = iges_param_reals(r, &p, 1, 12, "matrix entries", v);
    iges_params_free(&p);
    if (st != SW_OK)
        return st;
    *out = sw_mat4_identity();
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 4; col++)
            out->m[col * 4 + row] = v[row * 4 + col];
    return SW_OK;
}

sw_status iges_entity_matrix(iges_reader *r, int e, sw_mat4 *out)
{
    *out = sw_mat4_identity();
    int de = r->ents[e].matrix_de;
    if (de == 0)
        return SW_OK;
    if (de < 0 || de % 2 == 0 || de > 2 * r->ent_count - 1)
        return iges_fail_entity(r, e, SW_ERR_FORMAT,
                                "expected a transformation matrix pointer in columns 49-56 (0 "
                                "or an odd D line up to %d), found %d",
                                2 * r->ent_count - 1, de);
    int me = (de - 1) / 2;
    if (r->ents[me].type != 124)
        return iges_fail_entity(r, e, SW_ERR_FORMAT,
                                "expected the transformation matrix pointer to name a 124, "
                                "found type %d at D line %d",
                                r->ents[me].type, de);
    sw_status st = iges_enter(r, me);
    if (st != SW_OK)
        return st;
    sw_mat4 own, parent;
    st = read_matrix(r, me, &own);
    if (st == SW_OK)
        st = iges_entity_matrix(r, me, &parent);   /* a 124's own 124 applies after it */
    if (st == SW_OK)
        *out = sw_mat4_mul(&parent, &own);
    iges_leave(r, me);
    return st;
}
