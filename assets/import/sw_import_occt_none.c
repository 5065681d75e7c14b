/* SPDX-License-Identifier: MIT */
/* The OCCT importer in a build without OpenCASCADE (SW_WITH_OCCT=OFF or the
 * library not installed): the interface exists so seamwalk-pack and the tests
 * link, and every call says how to get STEP support. */
#include "sw_import_occt.h"
#include "sw_occt_measure.h"

static sw_status without_occt(const char *path, sw_error *err)
{
    return sw_error_set(err, SW_ERR_UNSUPPORTED,
                        "%s: built without STEP support (install OpenCASCADE: "
                        "libocct-data-exchange-dev)",
                        path ? path : "(null)");
}

int sw_import_occt_available(void)
{
    return 0;
}

sw_status sw_import_occt_file(const char *path, const sw_import_options *options,
                              sw_model *model, sw_import_report *report, sw_error *err)
{
    (void)options;
    (void)model;
    (void)report;
    return without_occt(path, err);
}

sw_status sw_occt_measure_file(const char *path, sw_occt_measure *out, sw_error *err)
{
    (void)out;
    return without_occt(path, err);
}

sw_status sw_occt_measure_sewing(const char *path, double tolerance_mm, sw_occt_sewing *out,
                                 sw_error *err)
{
    (void)tolerance_mm;
    (void)out;
    return without_occt(path, err);
}
