/* SPDX-License-Identifier: MIT */
/* seamwalk-pack verify's tessellation proof (assets/pack/sw_pack_verify_tess.h):
 * a pack whose surfaces all tessellate passes at every seam state; one
 * with a surface the runtime would leave out (a trim crossing itself) fails,
 * naming the surface and why. */
#include <stdlib.h>
#include <string.h>

#include "model_shapes.h"
#include "sw_pack_verify_tess.h"
#include "sw_pack_write.h"
#include "sw_seam_sew.h"
#include "sw_seam_simplify.h"
#include "sw_test.h"

/* A loop of straight trims through the given (u, v) corners, closed. */
typedef struct polygon {
    double knots[4];
    double ctrl[8][8];
    sw_nurbs_curve curves[8];
} polygon;

static void polygon_init(polygon *p, const double (*corner)[2], int n)
{
    const double k[4] = {0, 0, 1, 1};
    memcpy(p->knots, k, sizeof k);
    for (int e = 0; e < n; e++) {
        const double *a = corner[e], *b = corner[(e + 1) % n];
        double *c = p->ctrl[e];
        c[0] = a[0], c[1] = a[1], c[2] = 0, c[3] = 1;
        c[4] = b[0], c[5] = b[1], c[6] = 0, c[7] = 1;
        p->curves[e] = (sw_nurbs_curve){1, 2, p->knots, c};
    }
}

/* The plane trimmed by the polygon, packed with its Seam Graph as
 * seamwalk-pack build packs it, then verified. */
static sw_status verify_plane_trimmed_by(const double (*corner)[2], int n,
                                         sw_pack_tess_report *report, sw_error *err)
{
    shape_plane plane;
    shape_plane_init(&plane, 3, 2, 2, 1, 1);
    polygon poly;
    polygon_init(&poly, corner, n);
    sw_model_loop_input loop[1] = {{poly.curves, NULL, (size_t)n, 1, NULL, NULL}};
    sw_model m;
    sw_model_init(&m);
    sw_seam_host seams = {0};
    sw_pack_contents contents;
    uint8_t *bytes = NULL;
    size_t size = 0;
    sw_status st = sw_model_add_surface(&m, &plane.surface, 0, loop, 1, err);
    if (st == SW_OK)
        st = sw_seam_sew_model(&m, NULL, &seams, NULL, err);
    if (st == SW_OK)
        st = sw_seam_simplify(&seams, err);
    if (st == SW_OK)
        st = sw_pack_contents_from_model(&m, &contents, err);
    if (st == SW_OK) {
        sw_seam_graph view = sw_seam_host_view(&seams);
        contents.seam = &view;
        st = sw_pack_serialize(&contents, &bytes, &size, err);
        sw_pack_contents_free(&contents);
    }
    sw_pack pack;
    if (st == SW_OK)
        st = sw_pack_open_memory(bytes, size, &pack, err);
    if (st == SW_OK)
        st = sw_pack_verify_tessellation(&pack, report, err);
    free(bytes);
    sw_seam_host_free(&seams);
    sw_model_free(&m);
    return st;
}

static void test_a_good_trim_tessellates_at_every_state(void)
{
    const double square[4][2] = {{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.8}, {0.2, 0.8}};
    sw_pack_tess_report r;
    sw_error err = {0};
    SW_CHECK_MSG(verify_plane_trimmed_by(square, 4, &r, &err) == SW_OK, "%s", err.message);
    SW_CHECK(r.surfaces == 1 && r.failed == 0 && r.holes_filled == 0);
    /* the finest state and coarser ones until the square is gone */
    SW_CHECK(r.states >= 2 && r.checks >= 1);
}

/* A bow tie: the trim crosses itself at (0.5, 0.5). The runtime's
 * tessellator refuses it, so the surface would be a hole. */
static void test_a_trim_crossing_itself_fails_verify(void)
{
    const double bow[4][2] = {{0.2, 0.2}, {0.8, 0.8}, {0.8, 0.2}, {0.2, 0.8}};
    sw_pack_tess_report r;
    sw_error err = {0};
    sw_status st = verify_plane_trimmed_by(bow, 4, &r, &err);
    SW_CHECK_MSG(st == SW_ERR_FORMAT, "got %s: %s", sw_status_name(st), err.message);
    SW_CHECK(r.failed >= 1);
    SW_CHECK_MSG(strstr(err.message, "surface 0 does not tessellate") != NULL, "%s", err.message);
    SW_CHECK_MSG(strstr(err.message, "cross") != NULL, "%s", err.message);
}

static void test_a_pack_without_seams_has_nothing_to_check(void)
{
    sw_pack pack = {0};
    sw_pack_tess_report r;
    SW_CHECK(sw_pack_verify_tessellation(&pack, &r, NULL) == SW_OK);
    SW_CHECK(r.surfaces == 0 && r.states == 0 && r.checks == 0);
}

int main(void)
{
    SW_RUN(test_a_good_trim_tessellates_at_every_state);
    SW_RUN(test_a_trim_crossing_itself_fails_verify);
    SW_RUN(test_a_pack_without_seams_has_nothing_to_check);
    return sw_test_finish();
}
