/* The client suite's output (tests/clients): writing what a client drew, so that
 * pfclientcompare can judge it against OSMesa's. Not part of any client's GL: plain C files.
 *   colour: a PAM file (RGB_ALPHA, row 0 at the top as image files have it);
 *   depth:  "PFDEPTH width height\n" and width x height floats in [0, 1], row 0 at the bottom.
 * The first line on stdout is GL_RENDERER, so a test can tell which GL drew. */
#ifndef CLIENT_OUTPUT_H
#define CLIENT_OUTPUT_H

#include <stdio.h>
#include <stdlib.h>

static int client_write_pam(const char *path, int width, int height, const unsigned char *rgba) {
  FILE *f = fopen(path, "wb");
  int y;
  if (!f) return 0;
  fprintf(f, "P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n", width, height);
  for (y = height - 1; y >= 0; --y) fwrite(rgba + (size_t)y * width * 4, 4, (size_t)width, f);
  return fclose(f) == 0;
}

static int client_write_depth(const char *path, int width, int height, const float *depth) {
  FILE *f = fopen(path, "wb");
  if (!f) return 0;
  fprintf(f, "PFDEPTH %d %d\n", width, height);
  fwrite(depth, sizeof(float), (size_t)width * height, f);
  return fclose(f) == 0;
}

/* Depth as OSMesaGetDepthBuffer lays it out (2 bytes: 16 bits; 4 bytes: Z in the low 24 bits)
 * or as primflow's pfGetDepthBuffer does (4 bytes, float when is_float), into floats. */
static float *client_depth_to_float(const void *depth, int width, int height, int bytes, int is_float) {
  size_t i, n = (size_t)width * height;
  float *out = (float *)malloc(n * sizeof(float));
  if (!out) return NULL;
  for (i = 0; i < n; ++i) {
    if (is_float) out[i] = ((const float *)depth)[i];
    else if (bytes == 2) out[i] = ((const unsigned short *)depth)[i] / 65535.0f;
    else out[i] = (float)((((const unsigned int *)depth)[i] & 0xffffffu) / 16777215.0);
  }
  return out;
}

#endif
