/* SPDX-License-Identifier: MIT */
/* What OpenCASCADE measures in a CAD file, as JSON on stdout, for
 * test_models.sh to hold packs against an independent reader:
 *   occt_measure FILE              faces, area, tight box
 *   occt_measure --sew MM FILE     its faces sewn as a soup at MM: free border
 * Exit 77 in a build without OpenCASCADE, 1 when OCCT cannot read the file. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_import_occt.h"
#include "sw_occt_measure.h"

static int measure_sewing(const char *tolerance, const char *path)
{
    char *end;
    double mm = strtod(tolerance, &end);
    if (*end || !(mm > 0)) {
        fprintf(stderr, "occt_measure: --sew wants a positive tolerance, got '%s'\n", tolerance);
        return 2;
    }
    sw_occt_sewing s;
    sw_error err = {SW_OK, ""};
    if (sw_occt_measure_sewing(path, mm, &s, &err) != SW_OK) {
        fprintf(stderr, "occt_measure: %s\n", err.message);
        return 1;
    }
    printf("{\"faces\": %zu, \"tolerance\": %.9g, \"free_edges\": %zu, \"free_length\": %.9g, "
           "\"length\": %.9g}\n", s.faces, mm, s.free_edges, s.free_length_mm,
           s.border_length_mm);
    return 0;
}

int main(int argc, char **argv)
{
    int sew = argc == 4 && strcmp(argv[1], "--sew") == 0;
    if (argc != 2 && !sew) {
        fprintf(stderr, "usage: occt_measure [--sew MM] FILE\n");
        return 2;
    }
    if (!sw_import_occt_available()) {
        printf("skipped: built without OpenCASCADE\n");
        return 77;
    }
    if (sew)
        return measure_sewing(argv[2], argv[3]);
    sw_occt_measure m;
    sw_error err = {SW_OK, ""};
    if (sw_occt_measure_file(argv[1], &m, &err) != SW_OK) {
        fprintf(stderr, "occt_measure: %s\n", err.message);
        return 1;
    }
    printf("{\"faces\": %zu, \"area_mm2\": %.17g,\n \"box\": {\"min\": [%.17g, %.17g, %.17g], "
           "\"max\": [%.17g, %.17g, %.17g]}}\n",
           m.faces, m.area_mm2, m.box_min[0], m.box_min[1], m.box_min[2], m.box_max[0],
           m.box_max[1], m.box_max[2]);
    return 0;
}
