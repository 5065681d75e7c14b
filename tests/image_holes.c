/* SPDX-License-Identifier: MIT */
/* image_holes TEST.png REFERENCE.png R,G,B [--inside R,G,B] [--margin PX] [--reach PX]
 *             [--max N] [--max-inside N] [--out HOLES.png] [--empty-ok]
 * Cracks and holes in a picture, told by pixels alone (no bookkeeping of the
 * program that drew it): both pictures are the same view drawn over the
 * background R,G,B, a colour the model never has, REFERENCE densely (the
 * same walk at a far finer bound). A pixel is a hole when the reference
 * shows the model there and more than PX pixels (--margin, default 2)
 * around it, so it is inside the reference's silhouette, not on its edge,
 * where a coarser tessellation may rightly cut a pixel off, and TEST shows
 * the background. One exception: where a front part's contour crosses a
 * rear part's silhouette, or a thin wedge of background ends, edges that
 * move by their bound can open a notch a few pixels into the union's
 * interior; candidates within --reach (default 3) pixels of TEST's open
 * pixels outside the interior are such notches (counted apart), not holes.
 * A crack or a missing surface lies farther in. With --inside, back faces were drawn flat in
 * that colour: the reference's back faces bound its interior as its
 * background does (a contour is a silhouette too), and TEST pixels of that
 * colour inside are the solid's inside showing through (a crack into it, or
 * a contour the coarser tessellation moved: counted apart, at most
 * --max-inside, default no limit). A pixel is of a colour when within 2
 * levels of it per channel. Prints the count, the model's interior pixels,
 * its pixels in both pictures and the first holes; --out writes the holes
 * in red over the test picture dimmed. Exit 0 when at most N (default
 * 0) holes, 1 when more, 2 on error (unreadable files, sizes that differ, a
 * reference without any model pixel, which compares nothing; with
 * --empty-ok such a reference is no error but a view with nothing to miss,
 * 0 holes: a walk's frame that looks past the model, tests/walk_pictures.py). */
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct picture {
    int w, h;
    unsigned char *rgb;
} picture;

static int load(const char *path, picture *p)
{
    int n;
    p->rgb = stbi_load(path, &p->w, &p->h, &n, 3);
    if (!p->rgb)
        fprintf(stderr, "image_holes: cannot read %s: %s\n", path, stbi_failure_reason());
    return p->rgb != NULL;
}

static int is_background(const unsigned char *px, const int bg[3])
{
    if (bg[0] < 0)
        return 0;
    for (int c = 0; c < 3; c++)
        if (abs(px[c] - bg[c]) > 2)
            return 0;
    return 1;
}

typedef struct options {
    int bg[3], inside[3], margin, reach;
    long max_holes, max_inside;
    const char *out;
    int empty_ok;
} options;

/* Not the model's outside: the background or, with --inside, a back face. */
static int is_open(const unsigned char *px, const options *o)
{
    return is_background(px, o->bg) || is_background(px, o->inside);
}

/* Inside the reference's silhouette: the model at every pixel within
 * margin (Euclidean) of (x, y); beyond the picture's edge counts as model
 * (the frame's edge is no silhouette). */
static int interior(const picture *ref, const options *o, int x, int y, int margin)
{
    for (int dy = -margin; dy <= margin; dy++)
        for (int dx = -margin; dx <= margin; dx++) {
            int u = x + dx, v = y + dy;
            if (dx * dx + dy * dy > margin * margin || u < 0 || v < 0 || u >= ref->w ||
                v >= ref->h)
                continue;
            if (is_open(ref->rgb + 3 * ((size_t)v * ref->w + u), o))
                return 0;
        }
    return 1;
}

static int parse_rgb(const char *text, int bg[3])
{
    int used = 0;
    if (sscanf(text, "%d,%d,%d%n", &bg[0], &bg[1], &bg[2], &used) != 3 || text[used])
        return 0;
    for (int c = 0; c < 3; c++)
        if (bg[c] < 0 || bg[c] > 255)
            return 0;
    return 1;
}

static int parse_options(int argc, char **argv, options *o)
{
    o->margin = 2, o->reach = 3, o->max_holes = 0, o->max_inside = -1, o->out = NULL;
    o->empty_ok = 0;
    o->inside[0] = o->inside[1] = o->inside[2] = -1;
    if (argc < 4 || !parse_rgb(argv[3], o->bg))
        return 0;
    for (int i = 4; i < argc; i++) {
        if (!strcmp(argv[i], "--empty-ok")) {
            o->empty_ok = 1;
            continue;
        }
        if (i + 1 >= argc)
            return 0;
        if (!strcmp(argv[i], "--margin"))
            o->margin = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--inside")) {
            if (!parse_rgb(argv[++i], o->inside))
                return 0;
        } else if (!strcmp(argv[i], "--max-inside"))
            o->max_inside = atol(argv[++i]);
        else if (!strcmp(argv[i], "--reach"))
            o->reach = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--max"))
            o->max_holes = atol(argv[++i]);
        else if (!strcmp(argv[i], "--out"))
            o->out = argv[++i];
        else
            return 0;
    }
    return o->margin >= 0 && o->margin <= 32 && o->reach >= 0 && o->reach <= 32 &&
           o->max_holes >= 0;
}

/* The holes' picture: the test dimmed, holes red. */
static int write_holes(const char *path, const picture *test, const unsigned char *hole)
{
    size_t n = (size_t)test->w * test->h;
    unsigned char *out = malloc(n * 3);
    if (!out)
        return 0;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            out[3 * i + c] = hole[i] ? (c == 0 ? 255 : 0) : (unsigned char)(test->rgb[3 * i + c] / 3);
    int ok = stbi_write_png(path, test->w, test->h, 3, out, test->w * 3);
    free(out);
    return ok;
}

/* mark[i]: 0 model in TEST, 1 TEST open (background or inside) outside the
 * reference's interior, 2 TEST open inside it (a hole candidate).
 * Candidates within reach pixels (Chebyshev) of a 1 become 4: notches where
 * silhouettes cross or a thin wedge of background ends (its tip moves along
 * the wedge by far more than the edges move across it). */
static void mark_notches(unsigned char *mark, int w, int h, int reach)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            unsigned char *m = &mark[(size_t)y * w + x];
            for (int v = y - reach; v <= y + reach && *m == 2; v++)
                for (int u = x - reach; u <= x + reach && *m == 2; u++)
                    if (u >= 0 && v >= 0 && u < w && v < h && mark[(size_t)v * w + u] == 1)
                        *m = 4;
        }
}

static int compare(const char *test_path, const char *ref_path, const picture *test,
                   const picture *ref, const options *o)
{
    size_t n = (size_t)ref->w * ref->h;
    unsigned char *mark = calloc(n, 1);
    if (!mark)
        return 2;
    long holes = 0, insides = 0, notches = 0, inside = 0, model = 0, test_model = 0;
    for (int y = 0; y < ref->h; y++)
        for (int x = 0; x < ref->w; x++) {
            size_t i = (size_t)y * ref->w + x;
            model += !is_open(ref->rgb + 3 * i, o);
            test_model += !is_open(test->rgb + 3 * i, o);
            int in = interior(ref, o, x, y, o->margin);
            inside += in;
            if (is_open(test->rgb + 3 * i, o))
                mark[i] = in ? 2 : 1;
        }
    mark_notches(mark, ref->w, ref->h, o->reach);
    for (size_t i = 0; i < n; i++) {
        notches += mark[i] == 4;
        if (mark[i] != 2)
            continue;
        int background = is_background(test->rgb + 3 * i, o->bg);
        holes += background, insides += !background;
        if (holes + insides <= 8)
            printf("  %s at %zu,%zu\n", background ? "hole" : "inside", i % (size_t)ref->w,
                   i / (size_t)ref->w);
    }
    for (size_t i = 0; i < n; i++)
        mark[i] = mark[i] == 2;
    int empty = model == 0 && !o->empty_ok;
    int rc = empty ? 2 : holes > o->max_holes || (o->max_inside >= 0 && insides > o->max_inside);
    if (empty)
        fprintf(stderr, "image_holes: %s shows no model over %d,%d,%d: nothing to compare\n",
                ref_path, o->bg[0], o->bg[1], o->bg[2]);
    printf("%s vs %s: %ld holes, %ld inside in %ld interior pixels of the model (%ld pixels, "
           "%ld in TEST; margin %d px; %ld notch pixels at crossing silhouettes, reach %d)\n",
           test_path, ref_path, holes, insides, inside, model, test_model, o->margin, notches,
           o->reach);
    if (o->out && holes && !write_holes(o->out, test, mark))
        fprintf(stderr, "image_holes: cannot write %s\n", o->out), rc = 2;
    free(mark);
    return rc;
}

int main(int argc, char **argv)
{
    options o;
    if (!parse_options(argc, argv, &o)) {
        fprintf(stderr, "usage: image_holes TEST.png REFERENCE.png R,G,B [--inside R,G,B] "
                        "[--margin PX] [--reach PX] [--max N] [--max-inside N] "
                        "[--out HOLES.png] [--empty-ok]\n");
        return 2;
    }
    picture test = { 0 }, ref = { 0 };
    int rc = 2;
    if (load(argv[1], &test) && load(argv[2], &ref)) {
        if (test.w != ref.w || test.h != ref.h)
            fprintf(stderr, "image_holes: %s is %dx%d, %s %dx%d\n", argv[1], test.w, test.h,
                    argv[2], ref.w, ref.h);
        else
            rc = compare(argv[1], argv[2], &test, &ref, &o);
    }
    stbi_image_free(test.rgb);
    stbi_image_free(ref.rgb);
    return rc;
}
