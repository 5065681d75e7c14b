/* SPDX-License-Identifier: MIT */
/* The KMS display's connector and mode choice (platform/sw_kms_choose.h) over
 * connector and mode lists built here as libdrm would report them. */
#include "sw_kms_choose.h"
#include "sw_test.h"

static void the_first_connected_connector_with_modes_is_taken(void)
{
    const sw_kms_connector_info c[] = {{0, 3}, {1, 0}, {1, 5}, {1, 2}};
    SW_CHECK(sw_kms_choose_connector(c, 4) == 2);
}

static void no_connected_connector_is_minus_one(void)
{
    const sw_kms_connector_info c[] = {{0, 3}, {1, 0}};
    SW_CHECK(sw_kms_choose_connector(c, 2) == -1);
    SW_CHECK(sw_kms_choose_connector(c, 0) == -1);
}

/* A monitor's list: the preferred mode need not be first or largest. */
static const sw_kms_mode_info monitor[] = {
    {3840, 2160, 30, 0}, {1920, 1080, 60, 1}, {1920, 1080, 50, 0},
    {1280, 720, 60, 0}, {1280, 720, 75, 0}, {640, 480, 60, 0},
};

static void without_a_wish_the_preferred_mode_is_taken(void)
{
    SW_CHECK(sw_kms_choose_mode(monitor, 6, 0, 0) == 1);
}

static void a_size_the_connector_has_is_taken_at_its_highest_refresh(void)
{
    SW_CHECK(sw_kms_choose_mode(monitor, 6, 1280, 720) == 4);
    SW_CHECK(sw_kms_choose_mode(monitor, 6, 640, 480) == 5);
}

static void a_size_the_connector_lacks_falls_back_to_the_preferred(void)
{
    SW_CHECK(sw_kms_choose_mode(monitor, 6, 1024, 768) == 1);
}

static void without_a_preferred_mode_the_largest_is_taken(void)
{
    const sw_kms_mode_info panel[] = {
        {1024, 768, 60, 0}, {1920, 1200, 50, 0}, {1920, 1200, 60, 0}, {800, 600, 60, 0},
    };
    SW_CHECK(sw_kms_choose_mode(panel, 4, 0, 0) == 2);   /* largest, then the faster */
    SW_CHECK(sw_kms_choose_mode(panel, 4, 7, 7) == 2);
}

static void no_modes_is_minus_one(void)
{
    SW_CHECK(sw_kms_choose_mode(monitor, 0, 0, 0) == -1);
}

int main(void)
{
    SW_RUN(the_first_connected_connector_with_modes_is_taken);
    SW_RUN(no_connected_connector_is_minus_one);
    SW_RUN(without_a_wish_the_preferred_mode_is_taken);
    SW_RUN(a_size_the_connector_has_is_taken_at_its_highest_refresh);
    SW_RUN(a_size_the_connector_lacks_falls_back_to_the_preferred);
    SW_RUN(without_a_preferred_mode_the_largest_is_taken);
    SW_RUN(no_modes_is_minus_one);
    return sw_test_finish();
}
