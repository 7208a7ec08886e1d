/* Why a run was noisy: probes timed beside the reference frame at each checkpoint (steady.h).
 * The reference frame slowing down says that the machine changed speed, not why.
 * - clock: one chain of dependent integer multiply-adds. Each step waits for the one before, so
 *   it uses a sliver of the core's units and its time follows the core's clock alone.
 * - throughput: eight independent chains of the same steps, which keep the core's multipliers
 *   busy. A second hardware thread on the same physical core (another tenant's, on a virtual
 *   machine's host) takes units from it: up to half its speed, with the clock unchanged.
 * - memory: a chase of dependent loads through a buffer larger than a core's own caches, which
 *   waits on the shared last-level cache and DRAM (which other tenants use too). */
#ifndef RETRO_BENCH_MACHINE_PROBE_H
#define RETRO_BENCH_MACHINE_PROBE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bytes the memory probe chases through: past any one core's L2 (1 to 2 MiB on the machines
 * the suite runs on), within a server's shared L3, as the 4 MiB packed maps the kernels read are. */
#define MACHINE_PROBE_BYTES ((size_t)4 << 20)

/* Builds the memory probe's buffer: one random cycle through all of it (Sattolo's shuffle from
 * a fixed seed, so every run chases the same cycle). Returns 0, or -1 when memory is short;
 * then machine_probe_memory_ms gives NaN. Call once, before the cases run. */
int machine_probe_init(void);
void machine_probe_free(void);

/* Median ms of 5 runs of a fixed chain of dependent multiply-adds: time per cycle of the core
 * that runs it, times a constant. */
double machine_probe_clock_ms(void);

/* Median ms of 5 runs of eight independent chains of the clock probe's steps, 10^6 each. */
double machine_probe_throughput_ms(void);

/* Median ms of 5 runs of a fixed number of dependent loads through the buffer, after one pass
 * through all of it: the cases between two checkpoints evict it, and the probe should time the
 * machine's shared cache, not how much of the buffer they left there. NaN without the buffer. */
double machine_probe_memory_ms(void);

#ifdef __cplusplus
}
#endif

#endif
