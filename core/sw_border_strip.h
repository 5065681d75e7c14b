/* SPDX-License-Identifier: MIT */
/* Border strips (paper 000, sections 4.2 and 4.3): the triangles that join
 * a mesh made for one state of a surface's border to the border as it is
 * now. A static level of detail is stored, and an older mesh kept, with
 * the border it was made in (the inner chain); the Seam Graph's front has
 * since moved, and the neighbours draw the border's current polyline (the
 * outer chain). The strip runs between the two chains, so the mesh drawn
 * with it ends exactly on the outer chain's vertices, the ones the
 * neighbours share, and no crack opens whatever each side's level.
 *
 * The paper steps along the two chains in the parameter domain, from one
 * marked vertex to the next. Here both chains are placed along the loop by
 * one number, t: the slot of the loop (core/sw_seam_graph.h) each point
 * stands at, plus a fraction for a point between slots. Slots never move,
 * so t means the same in every state of the front, and two points at the
 * same t are the same place on the loop. Stepping both chains in t makes a
 * closed band of a + b triangles: every edge of each chain is used once,
 * the rungs between the chains twice (once each way), so the strip, the
 * inner mesh and the neighbours form one surface with no hole, even where
 * the chains cross (a coarse chain's chord on the other side of a fine
 * one): the band then folds over itself, within the chains' error of the
 * surface, but leaves no pixel open.
 *
 * Called by whoever makes a mesh for drawing (the host, building static
 * levels, and the walk's makers); no allocation, no state. */
#ifndef SW_BORDER_STRIP_H
#define SW_BORDER_STRIP_H

#include <stdint.h>

typedef struct sw_strip_point {
    uint32_t vertex;   /* the caller's vertex number */
    float t;           /* where it stands along the loop: slot + fraction, in [0, period) */
} sw_strip_point;

/* Triangles in the strip of chains of a and b points (the size of the
 * caller's output: 3 times that many indices). */
static inline uint32_t sw_border_strip_triangles(uint32_t a, uint32_t b) { return a + b; }

/* 1 when chain[0 .. n) goes once round the loop in t (each t in [0, period),
 * never decreasing except once, where it wraps): what sw_border_strip
 * needs. A pack's stored chains are checked with it on load. */
int sw_border_chain_valid(const sw_strip_point *chain, uint32_t n, float period);

/* The strip between the closed chains outer[0 .. a) and inner[0 .. b),
 * both valid (above) for the same loop of period slots, into tris as vertex
 * triples: sw_border_strip_triangles(a, b) of them, each wound the same
 * way in (t, from outer to inner): (outer, outer, inner) or (outer, inner,
 * inner). Which way that faces in space depends on the loop's direction:
 * the caller turns them to the surface's side. Returns the triangles
 * written; 0 (nothing written) when a chain is empty or not valid. */
uint32_t sw_border_strip(const sw_strip_point *outer, uint32_t a, const sw_strip_point *inner,
                         uint32_t b, float period, uint32_t *tris);

#endif
