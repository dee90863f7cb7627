/* SPDX-License-Identifier: Apache-2.0 */
/* Backend-independent parts of the dht test layer: PRNG and helpers. */
#include "dht.h"
#include <string.h>

#ifndef DHT_DEFAULT_SEED
#define DHT_DEFAULT_SEED 0x5eed2026u
#endif

static uint64_t dht_state = DHT_DEFAULT_SEED;
static uint64_t dht_seed_value = DHT_DEFAULT_SEED;

uint64_t dht_seed(void) { return dht_seed_value; }

void dht_reseed(uint64_t s)
{
    dht_seed_value = s;
    dht_state = s ? s : 0x9e3779b97f4a7c15ull;
}

uint32_t dht_rand_u32(void)
{
    uint64_t x = dht_state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    dht_state = x;
    return (uint32_t)((x * 0x2545F4914F6CDD1Dull) >> 32);
}

double dht_rand_uniform(double lo, double hi)
{
    uint64_t hi32 = dht_rand_u32(), lo32 = dht_rand_u32();
    double u = (double)((hi32 << 21) ^ lo32) / 9007199254740992.0; /* 53 bits */
    return lo + (hi - lo) * u;
}

void dht_memcpy4(void *dst, const void *src) { memcpy(dst, src, 4); }

uint32_t dht_f32_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

float dht_f32_from_bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

int dht_parse_seed(const char *s, uint64_t *seed)
{
    uint64_t v = 0;
    size_t i, n = 0;
    if (s == NULL || s[0] == '\0') return 0;
    if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        for (i = 2; s[i] != '\0'; i++) {
            char ch = s[i];
            unsigned d;
            if (ch >= '0' && ch <= '9') d = (unsigned)(ch - '0');
            else if (ch >= 'a' && ch <= 'f') d = (unsigned)(ch - 'a') + 10u;
            else if (ch >= 'A' && ch <= 'F') d = (unsigned)(ch - 'A') + 10u;
            else return 0;
            if (++n > 16u) return 0;
            v = (v << 4) | d;
        }
        if (n == 0u) return 0;
    } else {
        if (s[0] == '0' && s[1] != '\0') return 0; /* 010: octal or decimal? */
        for (i = 0; s[i] != '\0'; i++) {
            unsigned d;
            if (s[i] < '0' || s[i] > '9') return 0;
            d = (unsigned)(s[i] - '0');
            if (v > (UINT64_MAX - d) / 10u) return 0;
            v = v * 10u + d;
        }
    }
    *seed = v;
    return 1;
}

long dht_iter(long n)
{
    long d = dht_iter_div();
    return (n / d > 0) ? n / d : 1;
}

/* ---- reach probes ---- */

/* DHT_REACH_RECORD 1 (host): the probes are kept and checked by the host
 * runner; 0 (targets, set by test/CMakeLists.txt): nothing is kept, the
 * table would not fit beside the suites in a 16 KB part's RAM. */
#ifndef DHT_REACH_RECORD
#define DHT_REACH_RECORD 1
#endif

#if DHT_REACH_RECORD

typedef struct {
    char name[48];
    int is_max;
    double v;
} dht_probe;

static dht_probe dht_probes[DHT_REACH_MAX_PROBES];
static size_t dht_nprobes;

static dht_probe *dht_probe_find(const char *name, size_t len)
{
    size_t i;
    for (i = 0; i < dht_nprobes; i++)
        if (strlen(dht_probes[i].name) == len && memcmp(dht_probes[i].name, name, len) == 0) return &dht_probes[i];
    return NULL;
}

static void dht_reach(const char *name, int is_max, double v)
{
    dht_probe *p = dht_probe_find(name, strlen(name));
    if (p == NULL) {
        /* a test error, not an input: fail where it is recorded */
        if (strlen(name) >= sizeof dht_probes[0].name || dht_nprobes >= DHT_REACH_MAX_PROBES)
            dht_fail(__FILE__, __LINE__, "reach probe \"%s\": name too long or more than %d probes", name,
                     DHT_REACH_MAX_PROBES);
        p = &dht_probes[dht_nprobes++];
        strcpy(p->name, name);
        p->is_max = is_max;
        p->v = v;
        return;
    }
    if (p->is_max != is_max)
        dht_fail(__FILE__, __LINE__, "reach probe \"%s\" recorded as both min and max", name);
    if (is_max ? v > p->v : v < p->v) p->v = v;
}

void dht_reach_min(const char *name, double v) { dht_reach(name, 0, v); }
void dht_reach_max(const char *name, double v) { dht_reach(name, 1, v); }

void dht_reach_report(void)
{
    size_t i;
    for (i = 0; i < dht_nprobes; i++)
        dht_printf("reach %s %s %.17g\n", dht_probes[i].name, dht_probes[i].is_max ? "max" : "min", dht_probes[i].v);
}

int dht_reach_value(const char *name, size_t len, int *is_max, double *v)
{
    const dht_probe *p = dht_probe_find(name, len);
    if (p == NULL) return 0;
    *is_max = p->is_max;
    *v = p->v;
    return 1;
}

#else

void dht_reach_min(const char *name, double v)
{
    (void)name;
    (void)v;
}

void dht_reach_max(const char *name, double v)
{
    (void)name;
    (void)v;
}

void dht_reach_report(void) {}

int dht_reach_value(const char *name, size_t len, int *is_max, double *v)
{
    (void)name;
    (void)len;
    (void)is_max;
    (void)v;
    return 0;
}

#endif
