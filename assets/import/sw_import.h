/* SPDX-License-Identifier: MIT */
/* What every CAD importer shares: its options (strictness, progress) and its
 * report (what was read, skipped, tolerated or computed). Host only. */
#ifndef SW_IMPORT_H
#define SW_IMPORT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Called now and then during long imports; fraction in [0, 1]. */
typedef void (*sw_progress_fn)(void *user, const char *stage, double fraction);

typedef struct sw_import_options {
    int strict;                 /* skipped entities and tolerated messages are errors */
    sw_progress_fn progress;    /* may be NULL */
    void *progress_user;
    double tolerance_mm;        /* 0: the file's model tolerance (or 0.01 mm if it has none) */
    /* OpenCASCADE's faces are converted on it (sw_parts.h); NULL: in order
     * here. The model is the same either way. */
    const struct sw_parts_runner *runner;
} sw_import_options;

enum { SW_IMPORT_KINDS = 16, SW_IMPORT_KIND_CHARS = 72 };

/* Occurrences counted by kind: the first SW_IMPORT_KINDS kinds by name
 * ("IGES 406", "STEP: Count of Parameters is not 2 for si_unit"), all of
 * them in total. */
typedef struct sw_import_tally {
    size_t total;
    char kind[SW_IMPORT_KINDS][SW_IMPORT_KIND_CHARS];
    size_t count[SW_IMPORT_KINDS];
    size_t kinds;
} sw_import_tally;

typedef struct sw_import_report {
    size_t faces;               /* trimmed surfaces added to the model */
    size_t pcurves_computed;    /* trims made by point inversion from model-space curves */
    size_t pcurves_reprojected; /* converted p-curves that strayed from their edge, projected
                                   again from its model-space curve */
    size_t faces_moved;         /* closed faces converted a period along: OpenCASCADE's
                                   conversion failed where they were */
    size_t faces_unrolled;      /* faces over more than their surface's period, put on a
                                   B-spline surface of their own range */
    /* Entities that could not be used and were left out (a face and what
     * it needs): the model lacks them. */
    sw_import_tally unsupported;
    /* Messages about the file that did not keep anything out of the model
     * (a malformed unit, a name that is not a string): counted, built on. */
    sw_import_tally messages;
    /* Of those, the ones no geometry depends on (a solid-angle unit): told
     * like the others, but --strict reads past them too. */
    size_t harmless;
    /* The first message in full, with its place ("#1691: Count of ..."), for
     * --strict's error. */
    char first_message[160];
    double units_to_mm;         /* the scale the file's units were converted with */
    double model_tolerance_mm;  /* from the file, 0 if it has none */
} sw_import_report;

/* Counts n occurrences of kind (cut to SW_IMPORT_KIND_CHARS - 1 bytes);
 * kinds beyond SW_IMPORT_KINDS are counted in total only. */
void sw_import_tally_add(sw_import_tally *tally, const char *kind, size_t n);

/* Counts one skipped entity of a kind in the report (NULL report: nothing). */
void sw_import_report_unsupported(sw_import_report *report, const char *kind);

/* Counts one tolerated message; the first one's full text (with its place)
 * is kept in report->first_message. */
void sw_import_report_message(sw_import_report *report, const char *kind, const char *full);

/* Counts one tolerated message that --strict tolerates too (no geometry
 * depends on what it is about); first_message stays for the others. */
void sw_import_report_harmless(sw_import_report *report, const char *kind);

/* The messages --strict refuses a file for: all but the harmless ones. */
size_t sw_import_report_strict_messages(const sw_import_report *report);

/* Adds one import's report into a running total (a scene of many files). */
void sw_import_report_merge(sw_import_report *total, const sw_import_report *one);

#ifdef __cplusplus
}
#endif

#endif
