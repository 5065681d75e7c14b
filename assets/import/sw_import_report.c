/* The import report every importer fills (sw_import.h). */
#include "sw_import.h"

#include <stdio.h>
#include <string.h>

void sw_import_report_unsupported(sw_import_report *report, const char *kind)
{
    if (!report)
        return;
    report->unsupported++;
    for (size_t i = 0; i < report->unsupported_kinds; i++)
        if (strcmp(report->unsupported_kind[i], kind) == 0) {
            report->unsupported_count[i]++;
            return;
        }
    if (report->unsupported_kinds == SW_IMPORT_KINDS)
        return;
    size_t k = report->unsupported_kinds++;
    snprintf(report->unsupported_kind[k], sizeof report->unsupported_kind[k], "%s", kind);
    report->unsupported_count[k] = 1;
}
