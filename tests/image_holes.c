/* image_holes TEST.png REFERENCE.png R,G,B [--margin PX] [--reach PX] [--max N]
 *             [--out HOLES.png]
 * Cracks and holes in a picture, told by pixels alone (no bookkeeping of the
 * program that drew it): both pictures are the same view drawn over the
 * background R,G,B, a colour the model never has, REFERENCE densely (the
 * same walk at a far finer bound). A pixel is a hole when the reference
 * shows the model there and more than PX pixels (--margin, default 2)
 * around it, so it is inside the reference's silhouette, not on its edge,
 * where a coarser tessellation may rightly cut a pixel off, and TEST shows
 * the background. One exception: where a front part's contour crosses a
 * rear part's silhouette, both may move by their bound and open a notch of
 * background a few pixels into the union's interior; background reached from
 * outside the interior through at most --reach (default 3) background pixels
 * of TEST is such a notch (counted apart), not a hole. A crack or a missing
 * surface lies farther in. A background pixel is one within 2 levels of
 * R,G,B per channel. Prints the
 * count, the model's interior pixels and the first holes; --out writes the
 * holes in red over the test picture dimmed. Exit 0 when at most N (default
 * 0) holes, 1 when more, 2 on error (unreadable files, sizes that differ, a
 * reference without any model pixel, which compares nothing). */
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
    for (int c = 0; c < 3; c++)
        if (abs(px[c] - bg[c]) > 2)
            return 0;
    return 1;
}

/* Inside the reference's silhouette: the model at every pixel within
 * margin (Euclidean) of (x, y); beyond the picture's edge counts as model
 * (the frame's edge is no silhouette). */
static int interior(const picture *ref, const int bg[3], int x, int y, int margin)
{
    for (int dy = -margin; dy <= margin; dy++)
        for (int dx = -margin; dx <= margin; dx++) {
            int u = x + dx, v = y + dy;
            if (dx * dx + dy * dy > margin * margin || u < 0 || v < 0 || u >= ref->w ||
                v >= ref->h)
                continue;
            if (is_background(ref->rgb + 3 * ((size_t)v * ref->w + u), bg))
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

typedef struct options {
    int bg[3], margin, reach;
    long max_holes;
    const char *out;
} options;

static int parse_options(int argc, char **argv, options *o)
{
    o->margin = 2, o->reach = 3, o->max_holes = 0, o->out = NULL;
    if (argc < 4 || !parse_rgb(argv[3], o->bg))
        return 0;
    for (int i = 4; i < argc; i++) {
        if (i + 1 >= argc)
            return 0;
        if (!strcmp(argv[i], "--margin"))
            o->margin = atoi(argv[++i]);
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

/* mark[i]: 0 model in TEST, 1 TEST background outside the reference's
 * interior, 2 TEST background inside it (a hole candidate). Candidates
 * within reach steps (8-connected, through candidates) of a 1 become 3:
 * notches at crossing silhouettes. Rounds of growth, reach of them. */
static void mark_notches(unsigned char *mark, int w, int h, int reach)
{
    for (int round = 0; round < reach; round++) {
        int grown = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                unsigned char *m = &mark[(size_t)y * w + x];
                if (*m != 2)
                    continue;
                for (int d = 0; d < 9 && *m == 2; d++) {
                    int u = x + d % 3 - 1, v = y + d / 3 - 1;
                    if (u >= 0 && v >= 0 && u < w && v < h &&
                        (mark[(size_t)v * w + u] == 1 || mark[(size_t)v * w + u] == 4))
                        *m = 5; /* reached this round; a 4 from the rounds before */
                }
                grown += *m == 5;
            }
        for (size_t i = 0; i < (size_t)w * h; i++)
            mark[i] = mark[i] == 5 ? 4 : mark[i];
        if (!grown)
            break;
    }
}

static int compare(const char *test_path, const char *ref_path, const picture *test,
                   const picture *ref, const options *o)
{
    size_t n = (size_t)ref->w * ref->h;
    unsigned char *mark = calloc(n, 1);
    if (!mark)
        return 2;
    long holes = 0, notches = 0, inside = 0, model = 0;
    for (int y = 0; y < ref->h; y++)
        for (int x = 0; x < ref->w; x++) {
            size_t i = (size_t)y * ref->w + x;
            model += !is_background(ref->rgb + 3 * i, o->bg);
            int in = interior(ref, o->bg, x, y, o->margin);
            inside += in;
            if (is_background(test->rgb + 3 * i, o->bg))
                mark[i] = in ? 2 : 1;
        }
    mark_notches(mark, ref->w, ref->h, o->reach);
    for (size_t i = 0; i < n; i++) {
        notches += mark[i] == 4;
        if (mark[i] != 2)
            continue;
        if (holes++ < 8)
            printf("  hole at %zu,%zu\n", i % (size_t)ref->w, i / (size_t)ref->w);
    }
    for (size_t i = 0; i < n; i++)
        mark[i] = mark[i] == 2;
    int rc = model == 0 ? 2 : holes > o->max_holes;
    if (model == 0)
        fprintf(stderr, "image_holes: %s shows no model over %d,%d,%d: nothing to compare\n",
                ref_path, o->bg[0], o->bg[1], o->bg[2]);
    printf("%s vs %s: %ld holes in %ld interior pixels of the model (%ld pixels; margin %d px; "
           "%ld notch pixels at crossing silhouettes, reach %d; at most %ld)\n", test_path,
           ref_path, holes, inside, model, o->margin, notches, o->reach, o->max_holes);
    if (o->out && holes && !write_holes(o->out, test, mark))
        fprintf(stderr, "image_holes: cannot write %s\n", o->out), rc = 2;
    free(mark);
    return rc;
}

int main(int argc, char **argv)
{
    options o;
    if (!parse_options(argc, argv, &o)) {
        fprintf(stderr, "usage: image_holes TEST.png REFERENCE.png R,G,B [--margin PX] "
                        "[--reach PX] [--max N] [--out HOLES.png]\n");
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
