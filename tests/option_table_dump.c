/* SPDX-License-Identifier: MIT */
/* Prints seamwalk's option table (firmware/program/sw_option_table.h), one
 * row a line, tab-separated, for tests/check_man.py to hold the man pages
 * to: name, arg, range, default, config section, config key, and test-only
 * or alias where it applies ("-" for an empty field). */
#include <stdio.h>

#include "sw_option_table.h"

static const char *or_dash(const char *s)
{
    return s && s[0] ? s : "-";
}

int main(void)
{
    for (size_t i = 0; i < sw_option_count; i++) {
        const sw_option_desc *d = &sw_option_table[i];
        char range[80], def[96];
        sw_option_format_range(d, range, sizeof range);
        sw_option_format_default(d, def, sizeof def);
        const char *kind = d->flags & SW_OPTION_TEST_ONLY ? "test-only"
                           : d->flags & SW_OPTION_ALIAS   ? "alias"
                                                          : "-";
        printf("%s\t%s\t%s\t%s\t%s\t%s\t%s\n", d->name, or_dash(d->arg), or_dash(range),
               or_dash(def), or_dash(d->section), or_dash(d->key), kind);
    }
    return ferror(stdout) ? 1 : 0;
}
