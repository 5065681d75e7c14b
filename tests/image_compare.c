/* SPDX-License-Identifier: MIT */
/* image_compare A.png B.png [--level L] [--max-fraction F]
 * Compares two pictures of the same size for the golden-image tests: a pixel
 * differs when any channel differs by more than L levels (default 8); the
 * pictures match when at most F of the pixels differ (default 0.0005 = 0.05%,
 * 38 pixels of a 320x240 view). Today's renders match their references
 * exactly; 0.5% let a scene without its spoon (0.48%) or without 18 of the
 * teapot's patches (0.43%) pass, so the tolerance is a tenth of that: room
 * for a few edge pixels that llvmpipe rounds differently between Mesa
 * versions, none for a moved, missing or recoloured object (test_walk.sh
 * golden keeps mutants that must fail). `image_compare --coverage A.png MIN` checks instead that at least MIN
 * of the pixels differ from the background. `image_compare --aspect A.png MIN MAX`
 * checks that the silhouette (the box of the pixels that differ from the
 * background) is between MIN and MAX times as tall as it is wide. Prints the figures; exit 0 on a match, 1 on a mismatch, 2 on error. */
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int channel_diff(const unsigned char *a, const unsigned char *b, int level)
{
    for (int c = 0; c < 3; c++) {
        int d = a[c] - b[c];
        if (d > level || d < -level)
            return 1;
    }
    return 0;
}

/* --coverage A.png MIN: the share of pixels that differ from the top-left
 * (background) pixel must be at least MIN: the model is in the picture. */
static int coverage(const char *path, double min_fraction)
{
    int w, h, n;
    unsigned char *a = stbi_load(path, &w, &h, &n, 3);
    if (!a) {
        fprintf(stderr, "image_compare: cannot read %s\n", path);
        return 2;
    }
    long covered = 0, total = (long)w * h;
    for (long p = 0; p < total; p++)
        covered += channel_diff(a + p * 3, a, 8);
    stbi_image_free(a);
    double fraction = (double)covered / total;
    printf("%s: %.2f%% of pixels show something other than the background (need %.2f%%)\n", path,
           100 * fraction, 100 * min_fraction);
    return fraction >= min_fraction ? 0 : 1;
}

/* --aspect A.png MIN MAX: the silhouette's height / width lies in [MIN, MAX],
 * which tells a part standing upright from one lying on its side. */
static int aspect(const char *path, double min_ratio, double max_ratio)
{
    int w, h, n;
    unsigned char *a = stbi_load(path, &w, &h, &n, 3);
    if (!a) {
        fprintf(stderr, "image_compare: cannot read %s\n", path);
        return 2;
    }
    int x0 = w, x1 = -1, y0 = h, y1 = -1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if (channel_diff(a + ((long)y * w + x) * 3, a, 8)) {
                x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0, y1 = y > y1 ? y : y1;
            }
    stbi_image_free(a);
    if (x1 < 0) {
        printf("%s: nothing but the background\n", path);
        return 1;
    }
    double ratio = (double)(y1 - y0 + 1) / (x1 - x0 + 1);
    printf("%s: silhouette %d x %d pixels, height / width %.3f (need %.3f..%.3f)\n", path,
           x1 - x0 + 1, y1 - y0 + 1, ratio, min_ratio, max_ratio);
    return ratio >= min_ratio && ratio <= max_ratio ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc == 4 && !strcmp(argv[1], "--coverage"))
        return coverage(argv[2], atof(argv[3]));
    if (argc == 5 && !strcmp(argv[1], "--aspect"))
        return aspect(argv[2], atof(argv[3]), atof(argv[4]));
    int level = 8;
    double max_fraction = 0.0005;
    if (argc < 3) {
        fprintf(stderr, "usage: %s A.png B.png [--level L] [--max-fraction F]\n", argv[0]);
        return 2;
    }
    for (int i = 3; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--level"))
            level = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--max-fraction"))
            max_fraction = atof(argv[i + 1]);
    }
    int wa, ha, wb, hb, n;
    unsigned char *a = stbi_load(argv[1], &wa, &ha, &n, 3);
    unsigned char *b = stbi_load(argv[2], &wb, &hb, &n, 3);
    if (!a || !b || wa != wb || ha != hb) {
        fprintf(stderr, "image_compare: %s\n",
                !a ? "cannot read the first picture"
                   : !b ? "cannot read the second picture" : "pictures differ in size");
        stbi_image_free(a);
        stbi_image_free(b);
        return 2;
    }
    long differing = 0, total = (long)wa * ha;
    for (long p = 0; p < total; p++)
        differing += channel_diff(a + p * 3, b + p * 3, level);
    double fraction = (double)differing / total;
    printf("%s vs %s: %ld of %ld pixels differ by more than %d levels (%.3f%%, limit %.3f%%)\n",
           argv[1], argv[2], differing, total, level, 100 * fraction, 100 * max_fraction);
    stbi_image_free(a);
    stbi_image_free(b);
    return fraction <= max_fraction ? 0 : 1;
}
