/* Binding threads to cores with hwloc. The benchmark pins its own thread with it; threaded
 * kernels can pin their workers the same way. Safe to call from several threads at once. */
#ifndef RETRO_BENCH_PIN_H
#define RETRO_BENCH_PIN_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Cores this process may run on (at least 1; 1 when hwloc cannot load the topology). */
int pin_core_count(void);

/* Processing units (hardware threads) this process may run on, at least 1. */
int pin_pu_count(void);

/* Binds the calling thread to one processing unit on each of the n cores first .. first+n-1
 * (logical core indexes, taken modulo the core count). Returns 0 and describes the binding
 * in note ("cores 0-1 (PU 0,1)"), or -1 with the reason in note and the binding unchanged. */
int pin_thread_to_cores(int first, int n, char *note, size_t len);

#ifdef __cplusplus
}
#endif

#endif
