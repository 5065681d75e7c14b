/* SPDX-License-Identifier: MIT */
/* Scenes built in parts, on one machine or a farm: `seamwalk-pack
 * build-part SCENE --prototype K -o PART` (seamwalk_pack_main.c) packs one
 * prototype as build does; `merge` places the parts' packs into the pack
 * build would write, byte for byte; `ninja` writes a build.ninja running
 * both, so ninja, or a distributed front end for it, schedules the parts
 * (no scheduler of seamwalk's own). Host only. */
#ifndef SEAMWALK_PACK_PARTS_H
#define SEAMWALK_PACK_PARTS_H

/* The commands: argv holds the words after the command's name. Exit
 * status 0 done, 1 failed (one line on stderr), 2 usage error. */
int sw_pack_cmd_merge(int argc, char **argv);
int sw_pack_cmd_ninja(int argc, char **argv);

#endif
