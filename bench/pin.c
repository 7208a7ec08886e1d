/* hwloc thread binding: one topology per process, loaded once on first use. */
#include <pthread.h>
#include <stdio.h>

#include <hwloc.h>

#include "pin.h"

static hwloc_topology_t topo;
static int topo_ok;
static pthread_once_t topo_once = PTHREAD_ONCE_INIT;

/* pthread_once, because a threaded kernel's workers may all ask for their core at the same
 * moment and hwloc topologies must not be loaded twice. */
static void topo_load(void)
{
    if (hwloc_topology_init(&topo))
        return;
    if (hwloc_topology_load(topo)) {
        hwloc_topology_destroy(topo);
        return;
    }
    topo_ok = 1;
}

static int count(hwloc_obj_type_t type)
{
    pthread_once(&topo_once, topo_load);
    if (!topo_ok)
        return 1;
    int n = hwloc_get_nbobjs_by_type(topo, type);
    return n > 0 ? n : 1;
}

int pin_core_count(void)
{
    return count(HWLOC_OBJ_CORE);
}

int pin_pu_count(void)
{
    return count(HWLOC_OBJ_PU);
}

int pin_thread_to_cores(int first, int n, char *note, size_t len)
{
    int cores = pin_core_count();
    if (!topo_ok) {
        snprintf(note, len, "not pinned: hwloc could not load the topology");
        return -1;
    }
    const struct hwloc_topology_support *sup = hwloc_topology_get_support(topo);
    if (!sup->cpubind->set_thisthread_cpubind) {
        snprintf(note, len, "not pinned: hwloc cannot bind threads on this system");
        return -1;
    }
    if (n < 1 || n > cores) {
        snprintf(note, len, "not pinned: %d cores asked, %d available", n, cores);
        return -1;
    }
    hwloc_bitmap_t set = hwloc_bitmap_alloc(), one = hwloc_bitmap_alloc();
    if (!set || !one) {
        hwloc_bitmap_free(set);
        hwloc_bitmap_free(one);
        snprintf(note, len, "not pinned: out of memory");
        return -1;
    }
    for (int i = 0; i < n; i++) {
        unsigned idx = (unsigned)((first + i) % cores);
        hwloc_obj_t core = hwloc_get_obj_by_type(topo, HWLOC_OBJ_CORE, idx);
        if (!core)
            continue;
        /* One PU per core, so that two of our threads never share a core's SMT siblings
         * and a lone thread does not migrate between siblings. */
        hwloc_bitmap_copy(one, core->cpuset);
        hwloc_bitmap_singlify(one);
        hwloc_bitmap_or(set, set, one);
    }
    int rc = -1;
    if (hwloc_bitmap_iszero(set))
        snprintf(note, len, "not pinned: no core objects in the topology");
    else if (hwloc_set_cpubind(topo, set, HWLOC_CPUBIND_THREAD))
        snprintf(note, len, "not pinned: hwloc_set_cpubind failed");
    else {
        char pus[128];
        hwloc_bitmap_list_snprintf(pus, sizeof pus, set);
        int last = (first + n - 1) % cores;
        if (n == 1)
            snprintf(note, len, "core %d (PU %s)", first % cores, pus);
        else
            snprintf(note, len, "cores %d-%d (PU %s)", first % cores, last, pus);
        rc = 0;
    }
    hwloc_bitmap_free(one);
    hwloc_bitmap_free(set);
    return rc;
}
