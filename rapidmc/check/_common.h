/* What the C files of rapidmc's compiled core share: hashing, growable arrays and
 * the search budget's attributes (see _native.c, _nodes.c and _packed.c). */
#ifndef RAPIDMC_COMMON_H
#define RAPIDMC_COMMON_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <string.h>

#define EMPTY (-1)
#define FIRST_CAPACITY 1024

static inline uint64_t mix64(uint64_t x)
{
    /* splitmix64's finaliser: every bit of the key reaches the slot index */
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return x;
}

/* ------------------------------------------------------------- growable arrays */

/* ``items`` (``*capacity`` items of ``size`` bytes) with room for ``wanted`` items, moved
 * when they grow by 1/``part`` (from 256) until they fit; ``reserve``: by half, so at most
 * a third of the room is ever spare, where doubling left up to half (the stored states'
 * arrays are most of a search's memory); NULL when out of memory. */
static inline void *reserve_by(void *items, Py_ssize_t *capacity, size_t size,
                               Py_ssize_t wanted, Py_ssize_t part)
{
    if (wanted <= *capacity)
        return items;
    Py_ssize_t grown = *capacity ? *capacity : 256;
    while (grown < wanted)
        grown += grown / part > 0 ? grown / part : 1;
    void *moved = PyMem_Realloc(items, grown * size);
    if (moved == NULL)
        return PyErr_NoMemory();
    *capacity = grown;
    return moved;
}

static inline void *reserve(void *items, Py_ssize_t *capacity, size_t size, Py_ssize_t wanted)
{
    return reserve_by(items, capacity, size, wanted, 2);
}

/* ``capacity`` hash slots, every one EMPTY; NULL when out of memory */
static inline int32_t *new_slots(Py_ssize_t capacity)
{
    int32_t *slots = PyMem_Malloc(capacity * sizeof(int32_t));
    if (slots == NULL) {
        PyErr_NoMemory();
        return NULL;
    }
    memset(slots, 0xff, capacity * sizeof(int32_t));     /* every slot EMPTY */
    return slots;
}

typedef struct {          /* a growable array of numbers below 2**31 */
    int32_t *items;
    Py_ssize_t length, capacity;
} Int32Vector;

static inline int vector32_push(Int32Vector *vector, int64_t item)
{
    int32_t *items = reserve(vector->items, &vector->capacity, sizeof(int32_t),
                             vector->length + 1);
    if (items == NULL)
        return -1;
    vector->items = items;
    vector->items[vector->length++] = (int32_t)item;
    return 0;
}

static inline void vector32_free(Int32Vector *vector)
{
    PyMem_Free(vector->items);
    vector->items = NULL;
    vector->length = vector->capacity = 0;
}

/* a Python list of the ints ``items[0 .. length - 1]`` (a new reference) */
static inline PyObject *int32_list(const int32_t *items, Py_ssize_t length)
{
    PyObject *list = PyList_New(length);
    if (list == NULL)
        return NULL;
    for (Py_ssize_t i = 0; i < length; i++) {
        PyObject *number = PyLong_FromLong(items[i]);
        if (number == NULL) {
            Py_DECREF(list);
            return NULL;
        }
        PyList_SET_ITEM(list, i, number);
    }
    return list;
}

typedef struct {          /* a growable array of 64-bit numbers */
    uint64_t *items;
    Py_ssize_t length, capacity;
} Uint64Vector;

static inline int vector64_push(Uint64Vector *vector, uint64_t item)
{
    uint64_t *items = reserve(vector->items, &vector->capacity, sizeof(uint64_t),
                              vector->length + 1);
    if (items == NULL)
        return -1;
    vector->items = items;
    vector->items[vector->length++] = item;
    return 0;
}

static inline void vector64_free(Uint64Vector *vector)
{
    PyMem_Free(vector->items);
    vector->items = NULL;
    vector->length = vector->capacity = 0;
}

/* an integer attribute of ``object``; INT64_MAX for infinity (a float); -1 with an error */
static inline int64_t integer_attribute(PyObject *object, const char *name)
{
    PyObject *value = PyObject_GetAttrString(object, name);
    if (value == NULL)
        return -1;
    int64_t number = INT64_MAX;
    if (PyLong_Check(value))
        number = PyLong_AsLongLong(value);
    else if (PyFloat_Check(value) && PyFloat_AS_DOUBLE(value) < 9e18)
        number = (int64_t)PyFloat_AS_DOUBLE(value);
    Py_DECREF(value);
    return number;
}

/* whether ``budget.reason`` is set (-1 with an error) */
static inline int budget_stopped(PyObject *budget)
{
    PyObject *reason = PyObject_GetAttrString(budget, "reason");
    if (reason == NULL)
        return -1;
    int stopped = reason != Py_None;
    Py_DECREF(reason);
    return stopped;
}

/* A breadth-first loop that stops with an exception (an ``OutOfTime`` its Python step
 * raised at the time limit) returns no counts: it leaves them on the budget as
 * ``budget.stopped_counts = (transitions, deadlocks, depth of the last stored state)``
 * for the search's statistics, keeping the exception it stops with. */
static inline void keep_counts(PyObject *budget, long long transitions, long long deadlocks,
                               long deepest)
{
    PyObject *type, *value, *traceback;
    PyErr_Fetch(&type, &value, &traceback);
    PyObject *counts = Py_BuildValue("(LLl)", transitions, deadlocks, deepest);
    if (counts == NULL || PyObject_SetAttrString(budget, "stopped_counts", counts) < 0)
        PyErr_Clear();              /* (the statistics stay short; the stop is what counts) */
    Py_XDECREF(counts);
    PyErr_Restore(type, value, traceback);
}


/* registers NodeTable and PartHashes (_nodes.c) in the module */
int nodes_register(PyObject *module);

/* The step machine of a PackedTable (_packed.c) for a search loop of another file
 * (_native.c's CycleSearch): ``packed_check(object)``: whether it is a PackedTable;
 * ``packed_successor_ids``: the machine's step of stored state ``id`` with its successors
 * interned, as the method ``successor_ids`` gives it: their ids in model order into
 * ``ids``, and per new one, in id order, the bits of valuation ``valuation`` (``bits``)
 * and whether the machine valued it (``valued``: 0 where Python must; every one where
 * ``valuation`` is -1, not compiled).  PACKED_STEPPED,
 * PACKED_UNSUPPORTED (Python steps the state; nothing was interned), -1 with an error. */
enum { PACKED_STEPPED = 0, PACKED_UNSUPPORTED = 1 };
int packed_check(PyObject *object);
int packed_successor_ids(PyObject *table, Py_ssize_t id, Py_ssize_t valuation,
                         Int32Vector *ids, Uint64Vector *bits, Int32Vector *valued);

/* registers PackedTable and packed_breadth_first (_packed.c) in the module */
int packed_register(PyObject *module);
extern PyMethodDef packed_functions[];

#endif
