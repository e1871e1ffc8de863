/*
 * test_source.h - an emulated external memory for stream tests (littlefs's
 * emulated block device in spirit): a byte array that serves read() calls,
 * checks every call against the contract (aligned to read_size, inside the
 * device, size > 0), counts calls and bytes, and fails on demand: at the
 * k-th read, or at the read that would pass a byte budget.
 * Also stores an in-RAM image in the raster or tiled layout, with padding
 * bytes poisoned so that a library reading them shows up in results.
 */
#ifndef SSDA_TEST_SOURCE_H
#define SSDA_TEST_SOURCE_H
#include <stdint.h>
#include "ssda/stream.h"

/* Value of bytes that belong to no pixel (row/tile padding, gaps). */
#define TEST_SOURCE_POISON 0xA5u

typedef struct {
    uint8_t *bytes;         /* device contents */
    uint32_t capacity;      /* bytes of the array behind it */
    uint32_t size;          /* device bytes: the capacity, or the stored
                               image's extent after test_source_store */
    uint32_t read_size;     /* granularity every read must respect (>= 1) */
    int fail_code;          /* negative code returned by an injected failure */
    int64_t fail_at_read;   /* 0-based index of the read to fail; -1 = never */
    int64_t fail_after;     /* fail the read that would take bytes_read past
                               this many bytes; -1 = never */
    uint64_t reads;         /* successful and failed calls */
    uint64_t bytes_read;    /* bytes of successful calls */
    uint64_t failures;      /* injected failures returned */
    uint64_t contract_violations; /* misaligned, empty or out-of-device calls */
} test_source_t;

/* Device over bytes[0 .. capacity) with granularity read_size; no failures. */
void test_source_init(test_source_t *dev, uint8_t *bytes, uint32_t capacity, uint32_t read_size);

/* Reset counters and failure injection (contents unchanged). */
void test_source_reset(test_source_t *dev);

/* The ssda_read_fn: context is a test_source_t. */
int test_source_read(void *context, uint32_t offset, void *buffer, uint32_t size);

/* Bytes a device must have to hold the image described by cfg (layout,
   geometry, offset, stride, tile_stride resolved as the library does),
   rounded up to read_size. */
uint32_t test_source_extent(const ssda_source_config_t *cfg);

/*
 * Fill dev->bytes with poison, then store the pixels of img in the layout
 * that cfg describes (cfg->stride and cfg->tile_stride may be 0: packed),
 * and shrink the device to the image's extent (test_source_extent), so a
 * read beyond the aligned image is a contract violation. img must have
 * cfg's width, height and format. Fails the test if the array is too small.
 */
void test_source_store(test_source_t *dev, const ssda_source_config_t *cfg,
                       const ssda_view_t *img);

/* A config for img in dev: read = test_source_read, the given layout, tile
   size, offset, strides, read_size and arena. */
ssda_source_config_t test_source_config(test_source_t *dev, const ssda_view_t *img,
                                        uint8_t layout, uint16_t tile_w, uint16_t tile_h,
                                        uint32_t offset, uint32_t stride,
                                        uint32_t tile_stride, uint32_t read_size,
                                        void *arena, size_t arena_size);

#endif
