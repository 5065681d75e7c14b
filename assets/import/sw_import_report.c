/* SPDX-License-Identifier: MIT */
/* The import report every importer fills (sw_import.h). */
#include "sw_import.h"

#include <stdio.h>
#include <string.h>

void sw_import_tally_add(sw_import_tally *tally, const char *kind, size_t n)
{
    tally->total += n;
    for (size_t i = 0; i < tally->kinds; i++)
        if (strncmp(tally->kind[i], kind, SW_IMPORT_KIND_CHARS - 1) == 0) {
            tally->count[i] += n;
            return;
        }
    if (tally->kinds == SW_IMPORT_KINDS)
        return;
    size_t k = tally->kinds++;
    snprintf(tally->kind[k], sizeof tally->kind[k], "%s", kind);
    tally->count[k] = n;
}

void sw_import_report_unsupported(sw_import_report *report, const char *kind)
{
    if (report)
        sw_import_tally_add(&report->unsupported, kind, 1);
}

void sw_import_report_message(sw_import_report *report, const char *kind, const char *full)
{
    if (!report)
        return;
    if (sw_import_report_strict_messages(report) == 0)
        snprintf(report->first_message, sizeof report->first_message, "%s", full ? full : kind);
    sw_import_tally_add(&report->messages, kind, 1);
}

void sw_import_report_harmless(sw_import_report *report, const char *kind)
{
    if (!report)
        return;
    sw_import_tally_add(&report->messages, kind, 1);
    report->harmless++;
}

size_t sw_import_report_strict_messages(const sw_import_report *report)
{
    return report->messages.total - report->harmless;
}

static void tally_merge(sw_import_tally *total, const sw_import_tally *one)
{
    size_t listed = 0;
    for (size_t k = 0; k < one->kinds; k++) {
        sw_import_tally_add(total, one->kind[k], one->count[k]);
        listed += one->count[k];
    }
    total->total += one->total - listed;  /* the unnamed kinds */
}

void sw_import_report_merge(sw_import_report *total, const sw_import_report *one)
{
    total->faces += one->faces;
    total->pcurves_computed += one->pcurves_computed;
    total->pcurves_reprojected += one->pcurves_reprojected;
    total->faces_moved += one->faces_moved;
    total->faces_unrolled += one->faces_unrolled;
    if (sw_import_report_strict_messages(total) == 0 && sw_import_report_strict_messages(one) > 0)
        memcpy(total->first_message, one->first_message, sizeof total->first_message);
    tally_merge(&total->unsupported, &one->unsupported);
    tally_merge(&total->messages, &one->messages);
    total->harmless += one->harmless;
    total->units_to_mm = one->units_to_mm;
    if (one->model_tolerance_mm > total->model_tolerance_mm)
        total->model_tolerance_mm = one->model_tolerance_mm;
}
