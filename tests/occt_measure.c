/* What OpenCASCADE measures in a CAD file, as JSON on stdout, for
 * test_models.sh to hold packs against an independent reader:
 *   occt_measure FILE
 * Exit 77 in a build without OpenCASCADE, 1 when OCCT cannot read the file. */
#include <stdio.h>

#include "sw_import_occt.h"
#include "sw_occt_measure.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: occt_measure FILE\n");
        return 2;
    }
    if (!sw_import_occt_available()) {
        printf("skipped: built without OpenCASCADE\n");
        return 77;
    }
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
