/* What every CAD importer shares: its options (strictness, progress) and its
 * report (what was read, skipped or computed). Host only. */
#ifndef SW_IMPORT_H
#define SW_IMPORT_H

#include <stddef.h>

/* Called now and then during long imports; fraction in [0, 1]. */
typedef void (*sw_progress_fn)(void *user, const char *stage, double fraction);

typedef struct sw_import_options {
    int strict;                 /* unsupported entities and repairs are errors, not warnings */
    sw_progress_fn progress;    /* may be NULL */
    void *progress_user;
    double tolerance_mm;        /* 0: the file's model tolerance (or 0.01 mm if it has none) */
} sw_import_options;

enum { SW_IMPORT_KINDS = 16 };

typedef struct sw_import_report {
    size_t faces;               /* trimmed surfaces added to the model */
    size_t pcurves_computed;    /* trims made by point inversion from model-space curves */
    size_t unsupported;         /* entities skipped, all kinds */
    /* The first few unsupported kinds, for the warning: "IGES 406", "STEP X". */
    char unsupported_kind[SW_IMPORT_KINDS][24];
    size_t unsupported_count[SW_IMPORT_KINDS];
    size_t unsupported_kinds;
    double units_to_mm;         /* the scale the file's units were converted with */
    double model_tolerance_mm;  /* from the file, 0 if it has none */
} sw_import_report;

/* Counts one skipped entity of a kind in the report (kinds beyond
 * SW_IMPORT_KINDS are counted in unsupported only). */
void sw_import_report_unsupported(sw_import_report *report, const char *kind);

#endif
