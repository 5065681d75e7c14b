/* SPDX-License-Identifier: MIT */
/* The calling thread's name as top, perf and gdb show it (Linux: 15
 * characters at most, longer is cut), so a profile of the walk says which
 * of its threads spent the time: sw-visibility, sw-worker, sw-loader,
 * sw-parts; the GL thread keeps the program's name. Best effort: a name
 * that cannot be set changes nothing else. */
#ifndef SW_THREAD_NAME_H
#define SW_THREAD_NAME_H

void sw_thread_name(const char *name);

#endif
