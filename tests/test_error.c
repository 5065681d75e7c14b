/* SPDX-License-Identifier: MIT */
/* Errors as values (core/sw_error.h): a message that quotes a file's bytes
 * never carries a control byte out, however it is built or cut. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_error.h"
#include "sw_test.h"

static int has_control(const char *s)
{
    for (; *s; s++)
        if ((unsigned char)*s < 0x20 || (unsigned char)*s == 0x7f)
            return 1;
    return 0;
}

static void control_bytes_become_escapes(void)
{
    sw_error err;
    SW_CHECK(sw_error_set(&err, SW_ERR_FORMAT, "a.ini:3: unknown key '%s'", "x\x1b[2Jy\t\x7f") ==
             SW_ERR_FORMAT);
    SW_CHECK(err.status == SW_ERR_FORMAT);
    SW_CHECK_MSG(strcmp(err.message, "a.ini:3: unknown key 'x\\x1b[2Jy\\x09\\x7f'") == 0, "%s",
                 err.message);
}

static void a_prefix_is_escaped_and_escaping_twice_changes_nothing(void)
{
    sw_error err;
    sw_error_set(&err, SW_ERR_IO, "bad \x01 byte");
    sw_error_prefix(&err, "file\n%s", "name");
    SW_CHECK_MSG(strcmp(err.message, "file\\x0aname: bad \\x01 byte") == 0, "%s", err.message);
}

static void a_long_message_is_cut_whole(void)
{
    char quoted[2 * SW_ERROR_MESSAGE_MAX];
    memset(quoted, 0x1b, sizeof quoted - 1);
    quoted[sizeof quoted - 1] = '\0';
    sw_error err;
    sw_error_set(&err, SW_ERR_FORMAT, "%s", quoted);
    size_t n = strlen(err.message);
    SW_CHECK(n < SW_ERROR_MESSAGE_MAX);
    SW_CHECK(n % 4 == 0);   /* escapes are never cut in half */
    SW_CHECK(!has_control(err.message));
    sw_error_prefix(&err, "%s", quoted);
    SW_CHECK(!has_control(err.message) && strlen(err.message) < SW_ERROR_MESSAGE_MAX);
}

/* Text printed outside an sw_error (a pack's names): the same escapes, and
 * no byte past max or the NUL. */
static void printed_text_is_escaped_within_its_size(void)
{
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    SW_CHECK(f != NULL);
    const char name[8] = {'a', 0x1b, '[', '2', 'J', 0x7f, 'z', 'q'};   /* no NUL in its 8 */
    sw_fput_escaped(f, name, 7);
    fputc('|', f);
    sw_fput_escaped(f, "b\tc\nd", SIZE_MAX);
    fclose(f);
    SW_CHECK_MSG(!strcmp(text, "a\\x1b[2J\\x7fz|b\\x09c\\x0ad"), "%s", text);
    free(text);
}

int main(void)
{
    SW_RUN(control_bytes_become_escapes);
    SW_RUN(a_prefix_is_escaped_and_escaping_twice_changes_nothing);
    SW_RUN(a_long_message_is_cut_whole);
    SW_RUN(printed_text_is_escaped_within_its_size);
    return sw_test_finish();
}
