/* The compiled search core of rapidmc: a state table and the emptiness search in C.
 *
 * Optional: setup.py builds it when a C compiler is at hand, and the pure Python engine
 * (states.py, emptiness.py) stays the reference; rapidmc/check/native.py says which
 * engine runs.  Both engines give every state the same id and explore in the same order,
 * so verdicts, counterexamples and counts are identical (tests/test_native_engine.py).
 *
 * Table: the hot path of ``states.StateTable.intern`` and ``__getitem__`` for collapsed
 * states.  A state is split by the model's ``split_state``; its first two components are
 * looked up in the Python dicts the Python table keeps (rare new ones are stored by the
 * Python methods ``_add_component`` and ``_tail_id``), the (first component, tail) pair
 * becomes a head id in a native hash table, and the 64-bit key (head << 32 | second) of
 * the state finds its id in a native open-addressing table (filled up to three quarters:
 * the keys are mixed well): 8 to 10 bytes of key and 5 to 11 of slots per state, nothing
 * per state in Python objects.
 *
 * CycleSearch: Couvreur's emptiness check (emptiness.py's ``_explore_from``) with its
 * numbers, dead flags, stacks and path in native arrays; the product's successors come
 * from the Python ``successor_keys``, or are computed here over an explored graph or a
 * packed table's step machine (_packed.c), Python stepping the states the machine
 * leaves to it.
 *
 * breadth_first: reachability.py's unlabelled loop (the run-time error search) over a
 * Table; the model's step, the predicate, the observer and the graph's rows stay Python
 * calls.
 */
#include "_common.h"


/* ======================================================================== Table */

typedef struct {
    PyObject_HEAD
    PyObject *split, *join;          /* the model's split_state and join_state */
    PyObject *components0, *components1;   /* part -> id (dicts of the Python table) */
    PyObject *values0, *values1;     /* id -> part (lists of the Python table) */
    PyObject *tail_parts;            /* tail id -> tuple of the parts after the first two */
    PyObject *tails;                 /* that tuple -> tail id (a dict of the Python table) */
    PyObject *last_tail;             /* the tail last looked up (a tuple) and its id */
    Py_ssize_t last_tail_id;
    /* heads: (first component id, tail id) -> head id */
    int32_t *head_first, *head_tail;
    Py_ssize_t heads, head_capacity;
    int32_t *head_slots;
    uint64_t head_mask;
    /* states: id -> key, and the open-addressing index key -> id */
    int64_t *keys;
    Py_ssize_t count, key_capacity;
    int32_t *slots;
    uint64_t mask;
} Table;

static PyObject *Table_new(PyTypeObject *type, PyObject *args, PyObject *kwargs)
{
    Table *self = (Table *)type->tp_alloc(type, 0);
    if (self == NULL)
        return NULL;
    self->last_tail_id = EMPTY;
    self->slots = new_slots(FIRST_CAPACITY);
    self->head_slots = new_slots(FIRST_CAPACITY);
    if (self->slots == NULL || self->head_slots == NULL) {
        Py_DECREF(self);
        return NULL;
    }
    self->mask = self->head_mask = FIRST_CAPACITY - 1;
    return (PyObject *)self;
}

static int Table_traverse(Table *self, visitproc visit, void *arg)
{
    Py_VISIT(self->split);
    Py_VISIT(self->join);
    Py_VISIT(self->components0);
    Py_VISIT(self->components1);
    Py_VISIT(self->values0);
    Py_VISIT(self->values1);
    Py_VISIT(self->tail_parts);
    Py_VISIT(self->tails);
    Py_VISIT(self->last_tail);
    return 0;
}

static int Table_clear(Table *self)
{
    Py_CLEAR(self->split);
    Py_CLEAR(self->join);
    Py_CLEAR(self->components0);
    Py_CLEAR(self->components1);
    Py_CLEAR(self->values0);
    Py_CLEAR(self->values1);
    Py_CLEAR(self->tail_parts);
    Py_CLEAR(self->tails);
    Py_CLEAR(self->last_tail);
    return 0;
}

static void Table_dealloc(Table *self)
{
    PyObject_GC_UnTrack(self);
    Table_clear(self);
    PyMem_Free(self->head_first);
    PyMem_Free(self->head_tail);
    PyMem_Free(self->head_slots);
    PyMem_Free(self->keys);
    PyMem_Free(self->slots);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* the Python table's attribute ``name``, item ``index`` when ``index`` >= 0 (a new reference) */
static PyObject *attribute_item(PyObject *self, const char *name, Py_ssize_t index)
{
    PyObject *value = PyObject_GetAttrString(self, name);
    if (value == NULL || index < 0)
        return value;
    PyObject *item = PySequence_GetItem(value, index);
    Py_DECREF(value);
    return item;
}

/* Bind the Python table's split/join and, once its components exist, its dicts and lists. */
static int table_bind(Table *self, Py_ssize_t width)
{
    if (self->split == NULL) {
        self->split = attribute_item((PyObject *)self, "_split", -1);
        self->join = attribute_item((PyObject *)self, "_join", -1);
        if (self->split == NULL || self->join == NULL)
            return -1;
    }
    if (width < 0 || self->components0 != NULL)
        return 0;
    PyObject *started = PyObject_CallMethod((PyObject *)self, "_start", "n", width);
    if (started == NULL)
        return -1;
    Py_DECREF(started);
    self->components0 = attribute_item((PyObject *)self, "_components", 0);
    self->components1 = attribute_item((PyObject *)self, "_components", 1);
    self->values0 = attribute_item((PyObject *)self, "_values", 0);
    self->values1 = attribute_item((PyObject *)self, "_values", 1);
    self->tail_parts = attribute_item((PyObject *)self, "_tail_parts", -1);
    self->tails = attribute_item((PyObject *)self, "_tails", -1);
    if (self->components0 == NULL || self->components1 == NULL || self->values0 == NULL ||
        self->values1 == NULL || self->tail_parts == NULL || self->tails == NULL)
        return -1;
    if (!PyDict_CheckExact(self->components0) || !PyDict_CheckExact(self->components1) ||
        !PyList_CheckExact(self->values0) || !PyList_CheckExact(self->values1) ||
        !PyList_CheckExact(self->tail_parts) || !PyDict_CheckExact(self->tails)) {
        PyErr_SetString(PyExc_TypeError, "native table: components must be dicts and lists");
        return -1;
    }
    return 0;
}

static Py_ssize_t as_index(PyObject *number)
{
    if (number == NULL)
        return -1;
    Py_ssize_t value = PyLong_AsSsize_t(number);
    Py_DECREF(number);
    return value;
}

/* The id of component ``index`` (0 or 1) of a state, stored by the Python table when new. */
static Py_ssize_t component_id(Table *self, int index, PyObject *part)
{
    PyObject *components = index == 0 ? self->components0 : self->components1;
    PyObject *found = PyDict_GetItemWithError(components, part);
    if (found != NULL)
        return PyLong_AsSsize_t(found);
    if (PyErr_Occurred())
        return -1;
    return as_index(PyObject_CallMethod((PyObject *)self, "_add_component", "iO", index, part));
}

/* The tail id of parts[2:], the last one's when they equal the last tail's, else found in
 * the Python table's ``_tails`` (its ``_tail_id`` stores a new one). */
static Py_ssize_t tail_id(Table *self, PyObject *parts)
{
    Py_ssize_t length = PyTuple_GET_SIZE(parts) - 2;
    PyObject *last = self->last_tail;
    if (last != NULL && PyTuple_GET_SIZE(last) == length) {
        Py_ssize_t i;
        for (i = 0; i < length; i++) {
            PyObject *a = PyTuple_GET_ITEM(parts, i + 2), *b = PyTuple_GET_ITEM(last, i);
            if (a == b)
                continue;
            int equal = PyObject_RichCompareBool(a, b, Py_EQ);
            if (equal < 0)
                return -1;
            if (!equal)
                break;
        }
        if (i == length)
            return self->last_tail_id;
    }
    PyObject *tail = PyTuple_GetSlice(parts, 2, length + 2);
    if (tail == NULL)
        return -1;
    PyObject *known = PyDict_GetItemWithError(self->tails, tail);
    Py_ssize_t found = known != NULL ? PyLong_AsSsize_t(known) : PyErr_Occurred() ? -1 :
        as_index(PyObject_CallMethod((PyObject *)self, "_tail_id", "(O)", tail));
    if (found < 0) {
        Py_DECREF(tail);
        return -1;
    }
    Py_XSETREF(self->last_tail, tail);
    self->last_tail_id = found;
    return found;
}

static uint64_t head_key(Table *self, Py_ssize_t head)
{
    return ((uint64_t)self->head_first[head] << 32) | (uint32_t)self->head_tail[head];
}

static uint64_t state_key(Table *self, Py_ssize_t id)
{
    return (uint64_t)self->keys[id];
}

/* ``*slots`` (an index of ``count`` entries whose keys ``key_of`` gives) twice as large */
static int grow_index(Table *self, int32_t **slots, uint64_t *mask, Py_ssize_t count,
                      uint64_t (*key_of)(Table *, Py_ssize_t))
{
    uint64_t capacity = (*mask + 1) * 2;
    int32_t *grown = new_slots(capacity);
    if (grown == NULL)
        return -1;
    for (Py_ssize_t entry = 0; entry < count; entry++) {
        uint64_t position = mix64(key_of(self, entry)) & (capacity - 1);
        while (grown[position] != EMPTY)
            position = (position + 1) & (capacity - 1);
        grown[position] = (int32_t)entry;
    }
    PyMem_Free(*slots);
    *slots = grown;
    *mask = capacity - 1;
    return 0;
}

/* The head id of (first, tail), added when new. */
static Py_ssize_t head_id(Table *self, Py_ssize_t first, Py_ssize_t tail)
{
    uint64_t position = mix64(((uint64_t)first << 32) | (uint32_t)tail) & self->head_mask;
    for (;;) {
        int32_t head = self->head_slots[position];
        if (head == EMPTY)
            break;
        if (self->head_first[head] == first && self->head_tail[head] == tail)
            return head;
        position = (position + 1) & self->head_mask;
    }
    if (self->heads == self->head_capacity) {
        Py_ssize_t capacity = self->head_capacity;     /* (both arrays grow alike) */
        int32_t *firsts = reserve(self->head_first, &capacity, sizeof(int32_t), self->heads + 1);
        if (firsts == NULL)
            return -1;
        self->head_first = firsts;
        int32_t *tails = reserve(self->head_tail, &self->head_capacity, sizeof(int32_t),
                                 self->heads + 1);
        if (tails == NULL)
            return -1;
        self->head_tail = tails;
    }
    Py_ssize_t head = self->heads++;
    self->head_first[head] = (int32_t)first;
    self->head_tail[head] = (int32_t)tail;
    self->head_slots[position] = (int32_t)head;
    if ((uint64_t)self->heads * 2 > self->head_mask + 1 &&
        grow_index(self, &self->head_slots, &self->head_mask, self->heads, head_key) < 0)
        return -1;
    return head;
}

/* The id of ``state`` (-1 when new and not ``add``; -2 on an error); ``*is_new`` says
 * whether it was new. */
/* The id of the state whose split parts (their node ids) are ``parts``, a tuple the caller
 * keeps; -2 on an error. */
static Py_ssize_t table_intern_parts(Table *self, PyObject *parts, int add, int *is_new)
{
    if (self->split == NULL && table_bind(self, -1) < 0)
        return -2;
    if (!PyTuple_CheckExact(parts) || PyTuple_GET_SIZE(parts) < 2) {
        PyErr_SetString(PyExc_TypeError, "split_state must return a tuple of 2 or more parts");
        return -2;
    }
    if (self->components0 == NULL && table_bind(self, PyTuple_GET_SIZE(parts)) < 0)
        return -2;
    Py_ssize_t first = component_id(self, 0, PyTuple_GET_ITEM(parts, 0));
    if (first < 0)
        return -2;
    Py_ssize_t second = component_id(self, 1, PyTuple_GET_ITEM(parts, 1));
    if (second < 0)
        return -2;
    Py_ssize_t tail = tail_id(self, parts);
    if (tail < 0)
        return -2;
    Py_ssize_t head = head_id(self, first, tail);
    if (head < 0)
        return -2;
    int64_t key = ((int64_t)head << 32) | (uint32_t)second;
    uint64_t position = mix64((uint64_t)key) & self->mask;
    for (;;) {
        int32_t id = self->slots[position];
        if (id == EMPTY)
            break;
        if (self->keys[id] == key) {
            *is_new = 0;
            return id;
        }
        position = (position + 1) & self->mask;
    }
    *is_new = 1;
    if (!add)
        return -1;
    if (self->count == self->key_capacity) {
        Py_ssize_t capacity = self->key_capacity ? self->key_capacity + self->key_capacity / 4
                                                 : FIRST_CAPACITY;
        int64_t *keys = PyMem_Realloc(self->keys, capacity * sizeof(int64_t));
        if (keys == NULL) {
            PyErr_NoMemory();
            return -2;
        }
        self->keys = keys;
        self->key_capacity = capacity;
    }
    Py_ssize_t id = self->count++;
    self->keys[id] = key;
    self->slots[position] = (int32_t)id;
    if ((uint64_t)self->count * 4 > (self->mask + 1) * 3 &&
        grow_index(self, &self->slots, &self->mask, self->count, state_key) < 0)
        return -2;
    return id;
}

static Py_ssize_t table_intern(Table *self, PyObject *state, int add, int *is_new)
{
    if (self->split == NULL && table_bind(self, -1) < 0)
        return -2;
    PyObject *parts = PyObject_CallOneArg(self->split, state);
    if (parts == NULL)
        return -2;
    Py_ssize_t id = table_intern_parts(self, parts, add, is_new);
    Py_DECREF(parts);
    return id;
}

/* The state of ``id``, rebuilt by the model's join_state (a new reference). */
static PyObject *table_state(Table *self, Py_ssize_t id)
{
    if (id < 0 || id >= self->count) {
        PyErr_SetString(PyExc_IndexError, "state id out of range");
        return NULL;
    }
    int64_t key = self->keys[id];
    Py_ssize_t head = (Py_ssize_t)(key >> 32), second = (Py_ssize_t)(key & 0xffffffff);
    PyObject *tail = PyList_GET_ITEM(self->tail_parts, self->head_tail[head]);
    Py_ssize_t length = PyTuple_GET_SIZE(tail);
    PyObject *parts = PyTuple_New(length + 2);
    if (parts == NULL)
        return NULL;
    PyObject *item = PyList_GET_ITEM(self->values0, self->head_first[head]);
    Py_INCREF(item);
    PyTuple_SET_ITEM(parts, 0, item);
    item = PyList_GET_ITEM(self->values1, second);
    Py_INCREF(item);
    PyTuple_SET_ITEM(parts, 1, item);
    for (Py_ssize_t i = 0; i < length; i++) {
        item = PyTuple_GET_ITEM(tail, i);
        Py_INCREF(item);
        PyTuple_SET_ITEM(parts, i + 2, item);
    }
    PyObject *state = PyObject_CallOneArg(self->join, parts);
    Py_DECREF(parts);
    return state;
}

static PyObject *Table_intern(Table *self, PyObject *const *args, Py_ssize_t nargs,
                              PyObject *kwnames)
{
    Py_ssize_t keywords = kwnames == NULL ? 0 : PyTuple_GET_SIZE(kwnames);
    if (nargs < 1 || nargs + keywords > 2 ||
        (keywords == 1 && !PyUnicode_Check(PyTuple_GET_ITEM(kwnames, 0))) ||
        (keywords == 1 && PyUnicode_CompareWithASCIIString(PyTuple_GET_ITEM(kwnames, 0),
                                                           "add") != 0)) {
        PyErr_SetString(PyExc_TypeError, "intern(state, add=True)");
        return NULL;
    }
    int add = 1;
    if (nargs + keywords == 2 && (add = PyObject_IsTrue(args[1])) < 0)
        return NULL;
    int is_new = 0;
    Py_ssize_t id = table_intern(self, args[0], add, &is_new);
    if (id == -2)
        return NULL;
    PyObject *number = PyLong_FromSsize_t(id);
    if (number == NULL)
        return NULL;
    PyObject *answer = PyTuple_Pack(2, number, is_new ? Py_True : Py_False);
    Py_DECREF(number);
    return answer;
}

/* intern_rows(rows, width) -> (ids, new): the states given by their split parts' node
 * ids, ``width`` 32-bit ids a state end to end in ``rows`` (a buffer), stored when new;
 * their ids (64-bit) and whether each was new (a byte each), as bytes. */
static PyObject *Table_intern_rows(Table *self, PyObject *args)
{
    Py_buffer rows;
    Py_ssize_t width;
    if (!PyArg_ParseTuple(args, "y*n", &rows, &width))
        return NULL;
    PyObject *ids = NULL, *news = NULL, *answer = NULL;
    if (width < 2 || rows.len % (4 * width) != 0) {
        PyErr_SetString(PyExc_ValueError, "intern_rows: rows of width 32-bit ids expected");
        goto done;
    }
    Py_ssize_t count = rows.len / (4 * width);
    ids = PyBytes_FromStringAndSize(NULL, count * (Py_ssize_t)sizeof(int64_t));
    news = PyBytes_FromStringAndSize(NULL, count);
    if (ids == NULL || news == NULL)
        goto done;
    int64_t *id_out = (int64_t *)PyBytes_AS_STRING(ids);
    char *new_out = PyBytes_AS_STRING(news);
    const uint32_t *row = (const uint32_t *)rows.buf;
    for (Py_ssize_t i = 0; i < count; i++, row += width) {
        PyObject *parts = PyTuple_New(width);
        if (parts == NULL)
            goto done;
        for (Py_ssize_t j = 0; j < width; j++) {
            PyObject *part = PyLong_FromUnsignedLong(row[j]);
            if (part == NULL) {
                Py_DECREF(parts);
                goto done;
            }
            PyTuple_SET_ITEM(parts, j, part);
        }
        int is_new = 0;
        Py_ssize_t id = table_intern_parts(self, parts, 1, &is_new);
        Py_DECREF(parts);
        if (id == -2)
            goto done;
        id_out[i] = id;
        new_out[i] = (char)is_new;
    }
    answer = PyTuple_Pack(2, ids, news);
done:
    Py_XDECREF(ids);
    Py_XDECREF(news);
    PyBuffer_Release(&rows);
    return answer;
}

static PyObject *Table_native_bytes(Table *self, PyObject *unused)
{
    size_t bytes = self->key_capacity * sizeof(int64_t) + (self->mask + 1) * sizeof(int32_t) +
                   self->head_capacity * 2 * sizeof(int32_t) +
                   (self->head_mask + 1) * sizeof(int32_t);
    return PyLong_FromSize_t(bytes);
}

static Py_ssize_t Table_length(Table *self)
{
    return self->count;
}

static PyObject *Table_item(Table *self, Py_ssize_t id)
{
    return table_state(self, id);
}

static PyMethodDef Table_methods[] = {
    {"intern", (PyCFunction)(void (*)(void))Table_intern, METH_FASTCALL | METH_KEYWORDS,
     "intern(state, add=True) -> (id, new): the id of state, stored when new and add "
     "(id -1 when new and not add)."},
    {"intern_rows", (PyCFunction)Table_intern_rows, METH_VARARGS,
     "intern_rows(rows, width) -> (ids, new): states given by their parts' node ids "
     "(width uint32 a state), stored when new; int64 ids and a byte per state, as bytes."},
    {"native_bytes", (PyCFunction)Table_native_bytes, METH_NOARGS,
     "Bytes of the native arrays: keys, slots and heads."},
    {NULL}
};

static PySequenceMethods Table_as_sequence = {
    .sq_length = (lenfunc)Table_length,
    .sq_item = (ssizeargfunc)Table_item,
};

static PyTypeObject TableType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rapidmc.check._native.Table",
    .tp_doc = "The hot path of a collapsed state table (subclassed by native_states).",
    .tp_basicsize = sizeof(Table),
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_BASETYPE | Py_TPFLAGS_HAVE_GC,
    .tp_new = Table_new,
    .tp_dealloc = (destructor)Table_dealloc,
    .tp_traverse = (traverseproc)Table_traverse,
    .tp_clear = (inquiry)Table_clear,
    .tp_methods = Table_methods,
    .tp_as_sequence = &Table_as_sequence,
};

/* =================================================================== CycleSearch */

typedef struct {
    PyObject_HEAD
    PyObject *successor_keys;        /* key -> list of product successor keys */
    PyObject *budget;                /* the SearchBudget */
    PyObject *accepting;             /* bytes-like: by automaton state, 1 if accepting */
    Py_ssize_t width;
    int32_t *number;                 /* product key -> discovery number, -1: unseen */
    Py_ssize_t number_length;
    uint8_t *dead;                   /* by number: 1 once its component is complete */
    Py_ssize_t stored, dead_capacity;
    Int32Vector active, roots;       /* numbers of live states; of component roots */
    uint8_t *root_accepting;         /* parallel to roots */
    Py_ssize_t root_accepting_capacity;
    /* the DFS path, the successors still to try (keys: below 2**31, as numbers are) and by
     * path position the first of its entries in pending */
    Int32Vector path_keys, pending, path_starts;
    long long transitions, max_depth;
    /* the product over an explored graph, computed here (``Product.native_successors``):
     * the graph's row starts and targets, its kept valuations, the search's expanded
     * flags, and per (automaton state, valuation & read) the automaton targets */
    PyObject *graph;                 /* (starts, targets, valuations, expanded) or NULL */
    int32_t *move_starts, *moves;    /* moves of (q, v): moves[move_starts[q * (read + 1) + v] ..] */
    int64_t read;
    Int32Vector found;               /* the successors of the state pushed last */
    /* bytes-like: by automaton state, 1 if every word is accepted from it (a product state
     * there ends a bad prefix), or NULL; the DFS path to the first such state seen */
    PyObject *universal, *bad_path;
    /* the product over a packed table's step machine, computed here
     * (``Product.native_machine``): the ModelStore, ``successor_keys`` that steps in
     * Python (for the states the machine leaves to it), the table the store selects
     * (``machine_table``, NULL: none taken yet, or the machine is not used), the index
     * of the machine's atoms; the valuations of the store's states are in the store's
     * array up to id ``flushed``, those of the next ones in ``unflushed`` (added to
     * the array before Python runs and every UNFLUSHED_VALUES: ``flush_values``); the
     * machine's answer for one state */
    PyObject *store, *python_keys, *table;
    Py_ssize_t valuation, flushed;
    Uint64Vector unflushed, bits;
    Int32Vector ids, valued;
} CycleSearch;

#define UNFLUSHED_VALUES 4096

/* the guard tables of ``Product.native_successors`` / ``native_machine`` into ``self`` */
static int take_moves(CycleSearch *self, PyObject *move_starts, PyObject *moves,
                      long long read)
{
    Py_ssize_t starts_size = PyBytes_GET_SIZE(move_starts);
    Py_ssize_t moves_size = PyBytes_GET_SIZE(moves);
    self->move_starts = PyMem_Malloc(starts_size + 1);
    self->moves = PyMem_Malloc(moves_size + 1);
    if (self->move_starts == NULL || self->moves == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    memcpy(self->move_starts, PyBytes_AS_STRING(move_starts), starts_size);
    memcpy(self->moves, PyBytes_AS_STRING(moves), moves_size);
    self->read = read;
    return 0;
}

static PyObject *CycleSearch_new(PyTypeObject *type, PyObject *args, PyObject *kwargs)
{
    PyObject *successor_keys, *accepting, *budget, *graph = Py_None, *universal = Py_None;
    PyObject *machine = Py_None;
    Py_ssize_t width;
    if (!PyArg_ParseTuple(args, "OOnO|OOO", &successor_keys, &accepting, &width, &budget,
                          &graph, &universal, &machine))
        return NULL;
    if (!PyBytes_Check(accepting) || (universal != Py_None && !PyBytes_Check(universal))) {
        PyErr_SetString(PyExc_TypeError, "accepting and universal must be bytes");
        return NULL;
    }
    CycleSearch *self = (CycleSearch *)type->tp_alloc(type, 0);
    if (self == NULL)
        return NULL;
    Py_INCREF(successor_keys);
    self->successor_keys = successor_keys;
    Py_INCREF(accepting);
    self->accepting = accepting;
    Py_INCREF(budget);
    self->budget = budget;
    self->width = width;
    if (universal != Py_None) {
        Py_INCREF(universal);
        self->universal = universal;
    }
    if (graph != Py_None) {
        PyObject *rows, *move_starts, *moves;
        long long read;
        if (!PyArg_ParseTuple(graph, "OSSL", &rows, &move_starts, &moves, &read) ||
                take_moves(self, move_starts, moves, read) < 0) {
            Py_DECREF(self);
            return NULL;
        }
        Py_INCREF(rows);
        self->graph = rows;
    }
    else if (machine != Py_None) {
        PyObject *store, *python_keys, *move_starts, *moves;
        long long read;
        if (!PyArg_ParseTuple(machine, "OOnSSL", &store, &python_keys, &self->valuation,
                              &move_starts, &moves, &read) ||
                take_moves(self, move_starts, moves, read) < 0) {
            Py_DECREF(self);
            return NULL;
        }
        self->store = Py_NewRef(store);
        self->python_keys = Py_NewRef(python_keys);
    }
    return (PyObject *)self;
}

static int CycleSearch_traverse(CycleSearch *self, visitproc visit, void *arg)
{
    Py_VISIT(self->successor_keys);
    Py_VISIT(self->budget);
    Py_VISIT(self->accepting);
    Py_VISIT(self->graph);
    Py_VISIT(self->universal);
    Py_VISIT(self->bad_path);
    Py_VISIT(self->store);
    Py_VISIT(self->python_keys);
    Py_VISIT(self->table);
    return 0;
}

static int CycleSearch_clear(CycleSearch *self)
{
    Py_CLEAR(self->successor_keys);
    Py_CLEAR(self->budget);
    Py_CLEAR(self->accepting);
    Py_CLEAR(self->graph);
    Py_CLEAR(self->universal);
    Py_CLEAR(self->bad_path);
    Py_CLEAR(self->store);
    Py_CLEAR(self->python_keys);
    Py_CLEAR(self->table);
    return 0;
}

static void CycleSearch_dealloc(CycleSearch *self)
{
    PyObject_GC_UnTrack(self);
    CycleSearch_clear(self);
    PyMem_Free(self->number);
    PyMem_Free(self->dead);
    PyMem_Free(self->root_accepting);
    vector32_free(&self->active);
    vector32_free(&self->roots);
    vector32_free(&self->path_keys);
    vector32_free(&self->path_starts);
    vector32_free(&self->pending);
    vector32_free(&self->found);
    PyMem_Free(self->move_starts);
    PyMem_Free(self->moves);
    vector64_free(&self->unflushed);
    vector64_free(&self->bits);
    vector32_free(&self->ids);
    vector32_free(&self->valued);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* ``number`` long enough for ``key`` (grown by an eighth more, as emptiness.py does) */
static int cover_key(CycleSearch *self, int64_t key)
{
    if (key < self->number_length)
        return 0;
    Py_ssize_t length = key + 1 + self->number_length / 8;
    int32_t *number = PyMem_Realloc(self->number, length * sizeof(int32_t));
    if (number == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    memset(number + self->number_length, 0xff,
           (length - self->number_length) * sizeof(int32_t));
    self->number = number;
    self->number_length = length;
    return 0;
}

static int push_root(CycleSearch *self, int64_t index, uint8_t accepting)
{
    if (vector32_push(&self->roots, index) < 0)
        return -1;
    uint8_t *flags = reserve(self->root_accepting, &self->root_accepting_capacity, 1,
                             self->roots.length);
    if (flags == NULL)
        return -1;
    self->root_accepting = flags;
    self->root_accepting[self->roots.length - 1] = accepting;
    return 0;
}

static int push_dead(CycleSearch *self)
{
    uint8_t *dead = reserve(self->dead, &self->dead_capacity, 1, self->stored + 1);
    if (dead == NULL)
        return -1;
    self->dead = dead;
    self->dead[self->stored++] = 0;
    return 0;
}

static int flush_values(CycleSearch *self);

/* budget.<name>(args...) as a truth value (-1 on an error); the store's valuations are
 * complete while it runs */
static int budget_says(CycleSearch *self, const char *name, const char *format, ...)
{
    if (flush_values(self) < 0)
        return -1;
    PyObject *method = PyObject_GetAttrString(self->budget, name);
    if (method == NULL)
        return -1;
    va_list arguments;
    va_start(arguments, format);
    PyObject *call_args = Py_VaBuildValue(format, arguments);
    va_end(arguments);
    if (call_args == NULL) {
        Py_DECREF(method);
        return -1;
    }
    PyObject *answer = PyObject_CallObject(method, call_args);
    Py_DECREF(method);
    Py_DECREF(call_args);
    if (answer == NULL)
        return -1;
    int truth = PyObject_IsTrue(answer);
    Py_DECREF(answer);
    return truth;
}

typedef struct {               /* the explored graph's arrays, while a search reads them */
    Py_buffer starts, targets, valuations, expanded;
    int held;
} GraphView;

static void release_graph(GraphView *view)
{
    if (view->held >= 1) PyBuffer_Release(&view->starts);
    if (view->held >= 2) PyBuffer_Release(&view->targets);
    if (view->held >= 3) PyBuffer_Release(&view->valuations);
    if (view->held >= 4) PyBuffer_Release(&view->expanded);
    view->held = 0;
}

static int hold_graph(CycleSearch *self, GraphView *view)
{
    view->held = 0;
    if (self->graph == NULL)
        return 0;
    PyObject *parts[4];
    if (!PyArg_ParseTuple(self->graph, "OOOO", &parts[0], &parts[1], &parts[2], &parts[3]))
        return -1;
    Py_buffer *buffers[4] = {&view->starts, &view->targets, &view->valuations, &view->expanded};
    for (int i = 0; i < 4; i++) {
        if (PyObject_GetBuffer(parts[i], buffers[i],
                               (i == 3 ? PyBUF_WRITABLE : PyBUF_SIMPLE) | PyBUF_FORMAT) < 0) {
            release_graph(view);
            return -1;
        }
        view->held = i + 1;
    }
    if (view->starts.itemsize != 4 || view->targets.itemsize != 4) {
        release_graph(view);
        PyErr_SetString(PyExc_TypeError, "the graph's rows must be 32-bit arrays");
        return -1;
    }
    return 0;
}

/* item ``index`` of an array of unsigned numbers of ``size`` bytes */
static inline uint64_t unsigned_item(const char *items, Py_ssize_t size, Py_ssize_t index)
{
    switch (size) {
    case 1: return ((const uint8_t *)items)[index];
    case 2: return ((const uint16_t *)items)[index];
    case 4: return ((const uint32_t *)items)[index];
    default: return ((const uint64_t *)items)[index];
    }
}

/* the product successors of (q, model state ``target`` with ``valuation``) appended to
 * ``self->found``, in the guard table's order */
static int add_moves(CycleSearch *self, int64_t q, int64_t target, uint64_t valuation)
{
    int64_t row = q * (self->read + 1) + (int64_t)(valuation & (uint64_t)self->read);
    for (int32_t m = self->move_starts[row]; m < self->move_starts[row + 1]; m++) {
        int64_t successor = target * self->width + self->moves[m];
        if (successor > INT32_MAX) {
            PyErr_SetString(PyExc_OverflowError, "product key beyond 2**31 "
                            "(the Python engine takes it: --engine python)");
            return -1;
        }
        if (vector32_push(&self->found, successor) < 0)
            return -1;
    }
    return 0;
}

/* ``Product.successor_keys`` over the explored graph: into ``self->found`` */
static int graph_successors(CycleSearch *self, GraphView *view, int64_t key)
{
    int64_t width = self->width;
    int64_t state = key / width, q = key % width;
    const int32_t *starts = view->starts.buf, *targets = view->targets.buf;
    ((uint8_t *)view->expanded.buf)[state] = 1;
    self->found.length = 0;
    for (int32_t at = starts[state]; at < starts[state + 1]; at++)
        if (add_moves(self, q, targets[at], unsigned_item(view->valuations.buf,
                                                          view->valuations.itemsize,
                                                          targets[at])) < 0)
            return -1;
    return 0;
}

/* ``successor_keys(key)`` (a Python callable giving a list) into ``self->found`` */
static int python_successors(CycleSearch *self, PyObject *successor_keys, int64_t key)
{
    PyObject *successors = PyObject_CallFunction(successor_keys, "L", (long long)key);
    if (successors == NULL)
        return -1;
    if (!PyList_CheckExact(successors)) {
        Py_DECREF(successors);
        PyErr_SetString(PyExc_TypeError, "successor_keys must return a list");
        return -1;
    }
    self->found.length = 0;
    for (Py_ssize_t i = 0; i < PyList_GET_SIZE(successors); i++) {
        int64_t successor = PyLong_AsLongLong(PyList_GET_ITEM(successors, i));
        if (successor > INT32_MAX && !PyErr_Occurred())
            PyErr_SetString(PyExc_OverflowError, "product key beyond 2**31 "
                            "(the Python engine takes it: --engine python)");
        if (PyErr_Occurred() || vector32_push(&self->found, successor) < 0) {
            Py_DECREF(successors);
            return -1;
        }
    }
    Py_DECREF(successors);
    return 0;
}

/* The valuations the machine gave since the last flush added to the store's array
 * (``ModelStore.add_valuations``): before any Python code runs that may read them. */
static int flush_values(CycleSearch *self)
{
    if (self->store == NULL || self->unflushed.length == 0)
        return 0;
    PyObject *answer = PyObject_CallMethod(
        self->store, "add_valuations", "y#", (const char *)self->unflushed.items,
        (Py_ssize_t)(self->unflushed.length * sizeof(uint64_t)));
    if (answer == NULL)
        return -1;
    Py_DECREF(answer);
    self->flushed += self->unflushed.length;
    self->unflushed.length = 0;
    return 0;
}

/* The store's valuations as a buffer of unsigned numbers into ``view``: 1, 0 where they
 * are not (beyond 64 atoms, a list), -1 */
static int hold_values(CycleSearch *self, Py_buffer *view)
{
    PyObject *valuations = PyObject_GetAttrString(self->store, "valuations");
    if (valuations == NULL)
        return -1;
    int held = PyObject_CheckBuffer(valuations) &&
        PyObject_GetBuffer(valuations, view, PyBUF_FORMAT) == 0;
    Py_DECREF(valuations);
    if (!held)
        return 0;
    const char *format = view->format != NULL ? view->format : "B";
    if (strchr("BHILQ", format[0]) == NULL || format[1] != 0 || view->itemsize > 8) {
        PyBuffer_Release(view);
        return 0;
    }
    return 1;
}

/* After Python ran (the valuations flushed before): the table the store selects
 * (``machine_table``) and how many valuations its array holds.  Where they are not
 * unsigned numbers, the machine is no longer used here (``self->table`` NULL):
 * Python's ``successor_keys`` gives every state's successors. */
static int sync_values(CycleSearch *self)
{
    Py_CLEAR(self->table);
    PyObject *table = PyObject_CallMethod(self->store, "machine_table", NULL);
    if (table == NULL)
        return -1;
    Py_buffer view;
    int held = packed_check(table) ? hold_values(self, &view) : 0;
    if (held > 0) {
        self->flushed = view.len / view.itemsize;
        self->table = table;
        PyBuffer_Release(&view);
    }
    else
        Py_DECREF(table);
    return held < 0 ? -1 : 0;
}

/* ``Product.successor_keys`` over the step machine into ``self->found``: the machine's
 * successors of the model state, distinct, in model order (``ModelStore.successor_ids``),
 * each with its valuation (the machine's for a new state, else Python's:
 * ``ModelStore.valuation_of``); where the machine leaves the state to Python, Python's
 * ``successor_keys`` without the machine (``python_keys``).  0 or -1. */
static int machine_product_successors(CycleSearch *self, int64_t key)
{
    int64_t state = key / self->width, q = key % self->width;
    int outcome = PACKED_UNSUPPORTED;
    if (self->table != NULL)
        outcome = packed_successor_ids(self->table, state, self->valuation, &self->ids,
                                       &self->bits, &self->valued);
    if (outcome < 0)
        return -1;
    if (outcome != PACKED_STEPPED) {
        if (flush_values(self) < 0 ||
                python_successors(self, self->table != NULL ? self->python_keys :
                                  self->successor_keys, key) < 0)
            return -1;
        return sync_values(self);
    }
    for (Py_ssize_t i = 0; i < self->bits.length; i++) {
        uint64_t value = self->bits.items[i];
        if (!self->valued.items[i]) {
            if (flush_values(self) < 0)
                return -1;
            PyObject *answer = PyObject_CallMethod(self->store, "valuation_of", "n",
                                                   self->flushed);
            if (answer == NULL)
                return -1;
            value = PyLong_AsUnsignedLongLong(answer);
            Py_DECREF(answer);
            if (value == (uint64_t)-1 && PyErr_Occurred())
                return -1;
        }
        if (vector64_push(&self->unflushed, value) < 0)
            return -1;
    }
    Py_buffer view;
    int held = 0;
    self->found.length = 0;
    const int32_t *ids = self->ids.items;
    for (Py_ssize_t i = 0; i < self->ids.length; i++) {
        Py_ssize_t j = 0;
        while (j < i && ids[j] != ids[i])
            j++;
        if (j < i)
            continue;                           /* (a repeat: ``distinct``) */
        uint64_t value;
        if (ids[i] >= self->flushed) {
            if (ids[i] - self->flushed >= self->unflushed.length) {
                PyErr_SetString(PyExc_RuntimeError, "a model state without its valuation");
                break;
            }
            value = self->unflushed.items[ids[i] - self->flushed];
        }
        else {
            if (!held && (held = hold_values(self, &view)) <= 0) {
                if (held == 0)
                    PyErr_SetString(PyExc_TypeError, "the valuations are no numbers");
                return -1;
            }
            value = unsigned_item(view.buf, view.itemsize, ids[i]);
        }
        if (add_moves(self, q, ids[i], value) < 0)
            break;
    }
    if (held)
        PyBuffer_Release(&view);
    if (PyErr_Occurred())
        return -1;
    return self->unflushed.length >= UNFLUSHED_VALUES ? flush_values(self) : 0;
}

/* The search from one initial key: 1 when an accepting cycle closed (the path is left in
 * path_keys and the component on roots), 0 when done or stopped by the budget, -1 on error.
 * One loop, step for step emptiness.py's ``_explore_from`` (push, try the next pending
 * successor, pop), so that the two engines can be read side by side. */
static int explore_from(CycleSearch *self, int64_t initial_key, GraphView *view)
{
    const uint8_t *accepting = (const uint8_t *)PyBytes_AS_STRING(self->accepting);
    int64_t width = self->width;
    /* emptiness.py's ``watching``: no bad prefix found yet, and the automaton has states
     * that end one */
    const uint8_t *universal = NULL;
    if (self->universal != NULL && self->bad_path == NULL) {
        const char *flags = PyBytes_AS_STRING(self->universal);
        for (Py_ssize_t q = 0; q < PyBytes_GET_SIZE(self->universal); q++)
            if (flags[q])
                universal = (const uint8_t *)flags;
    }
    int64_t max_states = integer_attribute(self->budget, "max_states");
    int64_t next_checkpoint = integer_attribute(self->budget, "next_checkpoint");
    if (max_states < 0 || next_checkpoint < 0 || cover_key(self, initial_key) < 0)
        return -1;
    self->path_keys.length = self->path_starts.length = self->pending.length = 0;
    int64_t key = initial_key;
    for (;;) {
        if (key >= 0) {         /* push: number it, put its successors on ``pending`` */
            int64_t index = self->stored;
            self->number[key] = (int32_t)index;
            if (push_dead(self) < 0 || vector32_push(&self->active, index) < 0 ||
                push_root(self, index, accepting[key % width]) < 0)
                return -1;
            int got = self->graph != NULL ? graph_successors(self, view, key) :
                self->store != NULL ? machine_product_successors(self, key) :
                python_successors(self, self->successor_keys, key);
            if (got < 0 || vector32_push(&self->path_starts, self->pending.length) < 0)
                return -1;
            self->transitions += self->found.length;
            for (Py_ssize_t i = self->found.length - 1; i >= 0; i--)
                if (cover_key(self, self->found.items[i]) < 0 ||
                    vector32_push(&self->pending, self->found.items[i]) < 0)
                    return -1;
            if (vector32_push(&self->path_keys, key) < 0)
                return -1;
            if (self->path_keys.length > self->max_depth)
                self->max_depth = self->path_keys.length;
            if (universal != NULL) {     /* emptiness.py's ``watching``: successors in order */
                Py_ssize_t start = self->path_starts.items[self->path_starts.length - 1];
                for (Py_ssize_t i = self->pending.length - 1; i >= start; i--)
                    if (universal[self->pending.items[i] % width]) {
                        if (vector32_push(&self->path_keys, self->pending.items[i]) < 0)
                            return -1;
                        self->bad_path = int32_list(self->path_keys.items,
                                                   self->path_keys.length);
                        self->path_keys.length--;
                        if (self->bad_path == NULL || budget_says(self, "saw_bad_prefix", "(L)",
                                                                  (long long)self->stored) < 0)
                            return -1;
                        max_states = integer_attribute(self->budget, "max_states");
                        if (max_states < 0)
                            return -1;
                        universal = NULL;
                        break;
                    }
            }
            key = -1;
        }
        else if (self->path_keys.length == 0)
            return 0;
        if (self->pending.length > self->path_starts.items[self->path_starts.length - 1]) {
            int64_t successor = self->pending.items[--self->pending.length];
            int64_t index = self->number[successor];
            if (index < 0) {
                int64_t stored = self->stored;
                if (stored >= max_states) {
                    int may = budget_says(self, "may_store", "(L)", (long long)stored);
                    if (may <= 0)
                        return may < 0 ? -1 : 0;
                }
                if (stored >= next_checkpoint) {
                    int going = budget_says(self, "checkpoint", "(LLn)", (long long)stored,
                                            self->transitions, self->path_keys.length);
                    if (going <= 0)
                        return going < 0 ? -1 : 0;
                    next_checkpoint = integer_attribute(self->budget, "next_checkpoint");
                    if (next_checkpoint < 0)
                        return -1;
                }
                key = successor;
            }
            else if (!self->dead[index]) {
                uint8_t merged = 0;
                int32_t *roots = self->roots.items;
                while (roots[self->roots.length - 1] > index) {
                    self->roots.length--;
                    merged |= self->root_accepting[self->roots.length];
                }
                self->root_accepting[self->roots.length - 1] |= merged;
                if (self->root_accepting[self->roots.length - 1])
                    return 1;
            }
        }
        else {
            int64_t popped = self->path_keys.items[--self->path_keys.length];
            self->path_starts.length--;
            int64_t index = self->number[popped];
            if (self->roots.items[self->roots.length - 1] == index) {
                self->roots.length--;
                while (self->active.length && self->active.items[self->active.length - 1] >= index)
                    self->dead[self->active.items[--self->active.length]] = 1;
            }
        }
    }
}

/* (DFS path up to the accepting component's root, set of the component's keys) */
static PyObject *violation(CycleSearch *self)
{
    int64_t root = self->roots.items[self->roots.length - 1];
    Py_ssize_t depth = self->path_keys.length;
    while (self->number[self->path_keys.items[depth - 1]] > root)
        depth--;
    PyObject *path = PyList_New(depth);
    PyObject *component = PySet_New(NULL);
    if (path == NULL || component == NULL)
        goto failed;
    for (Py_ssize_t i = 0; i < depth; i++) {
        PyObject *key = PyLong_FromLongLong(self->path_keys.items[i]);
        if (key == NULL)
            goto failed;
        PyList_SET_ITEM(path, i, key);
    }
    for (Py_ssize_t key = 0; key < self->number_length; key++) {
        int32_t index = self->number[key];
        if (index >= root && !self->dead[index]) {
            PyObject *number = PyLong_FromSsize_t(key);
            if (number == NULL || PySet_Add(component, number) < 0) {
                Py_XDECREF(number);
                goto failed;
            }
            Py_DECREF(number);
        }
    }
    return Py_BuildValue("(NN)", path, component);
failed:
    Py_XDECREF(path);
    Py_XDECREF(component);
    return NULL;
}

static PyObject *CycleSearch_explore_from(CycleSearch *self, PyObject *argument)
{
    int64_t key = PyLong_AsLongLong(argument);
    if (key == -1 && PyErr_Occurred())
        return NULL;
    if (key < 0 || key > INT32_MAX) {
        PyErr_SetString(PyExc_OverflowError, "product key beyond 2**31");
        return NULL;
    }
    GraphView view;
    if (hold_graph(self, &view) < 0)
        return NULL;
    /* (Python may have added states and valuations, or selected another search) */
    int found = self->store != NULL && sync_values(self) < 0 ? -1 :
        explore_from(self, key, &view);
    release_graph(&view);
    if (found < 0 || flush_values(self) < 0)
        return NULL;
    if (found == 0)
        Py_RETURN_NONE;
    return violation(self);
}

static PyObject *CycleSearch_contains_key(CycleSearch *self, PyObject *argument)
{
    int64_t key = PyLong_AsLongLong(argument);
    if (key == -1 && PyErr_Occurred())
        return NULL;
    return PyBool_FromLong(key >= 0 && key < self->number_length && self->number[key] >= 0);
}

static PyObject *CycleSearch_number_of(CycleSearch *self, PyObject *argument)
{
    int64_t key = PyLong_AsLongLong(argument);
    if (key == -1 && PyErr_Occurred())
        return NULL;
    return PyLong_FromLong(key >= 0 && key < self->number_length ? self->number[key] : -1);
}

static PyObject *CycleSearch_bad_path(CycleSearch *self, PyObject *unused)
{
    PyObject *found = self->bad_path != NULL ? self->bad_path : Py_None;
    Py_INCREF(found);
    return found;
}

static PyObject *CycleSearch_counts(CycleSearch *self, PyObject *unused)
{
    size_t bytes = self->number_length * sizeof(int32_t) + self->dead_capacity +
                   (self->active.capacity + self->roots.capacity + self->path_starts.capacity +
                    self->path_keys.capacity + self->pending.capacity) * sizeof(int32_t) +
                   self->root_accepting_capacity;
    return Py_BuildValue("{sn,sL,sL,sn}", "stored", self->stored, "transitions",
                         self->transitions, "max_depth", self->max_depth, "bytes",
                         (Py_ssize_t)bytes);
}

static PyMethodDef CycleSearch_methods[] = {
    {"explore_from", (PyCFunction)CycleSearch_explore_from, METH_O,
     "explore_from(key) -> None, or (path keys, component keys) of an accepting cycle."},
    {"contains_key", (PyCFunction)CycleSearch_contains_key, METH_O,
     "Whether the search has stored the product key."},
    {"number_of", (PyCFunction)CycleSearch_number_of, METH_O,
     "The discovery number of a product key (-1: unseen)."},
    {"bad_path", (PyCFunction)CycleSearch_bad_path, METH_NOARGS,
     "The DFS path to the first state pushed that ends a bad prefix, or None."},
    {"counts", (PyCFunction)CycleSearch_counts, METH_NOARGS,
     "{stored, transitions, max_depth, bytes} of the search so far."},
    {NULL}
};

static PyTypeObject CycleSearchType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rapidmc.check._native.CycleSearch",
    .tp_doc = "CycleSearch(successor_keys, accepting, width, budget): Couvreur's emptiness "
              "check in native arrays.",
    .tp_basicsize = sizeof(CycleSearch),
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC,
    .tp_new = CycleSearch_new,
    .tp_dealloc = (destructor)CycleSearch_dealloc,
    .tp_traverse = (traverseproc)CycleSearch_traverse,
    .tp_clear = (inquiry)CycleSearch_clear,
    .tp_methods = CycleSearch_methods,
};

/* ================================================================ breadth first */

/* ``sequence.append(number)`` for an array of ints */
static int append_number(PyObject *sequence, int64_t number)
{
    PyObject *item = PyLong_FromLongLong(number);
    if (item == NULL)
        return -1;
    PyObject *done = PyObject_CallMethod(sequence, "append", "(O)", item);
    Py_DECREF(item);
    if (done == NULL)
        return -1;
    Py_DECREF(done);
    return 0;
}

/* Depths without an array: a breadth-first search stores states level by level, so the
 * states of the level being expanded end where the stored states ended when its first
 * state was expanded (``level_end``), and each new state is one level deeper. */
typedef struct {                 /* what one run of the breadth-first loop works with */
    Table *table;
    PyObject *targets_of, *observe, *predicate, *parent, *depth, *budget, *record;
    int deadlock_is_target;
    long depth_now, deepest;     /* the depth of the states expanded now; of the last stored */
    Py_ssize_t level_end;        /* the first id one level deeper than depth_now */
    int64_t max_states, next_checkpoint;
    long long transitions, deadlocks;
} BreadthFirst;

enum { GO_ON = 0, FOUND = 1, STOPPED = 2, FAILED = -1 };

/* Store one successor of ``frontier`` (its id in ``*id``): GO_ON, FOUND (the predicate
 * holds there), STOPPED (the budget says so) or FAILED. */
static int visit_successor(BreadthFirst *search, Py_ssize_t frontier, PyObject *successor,
                           Py_ssize_t *id)
{
    Py_ssize_t stored = search->table->count;
    int is_new = 0;
    *id = table_intern(search->table, successor, stored < search->max_states, &is_new);
    if (*id == -2)
        return FAILED;
    if (!is_new)
        return GO_ON;
    if (*id < 0) {              /* the state limit: ``may_store`` sets the reason */
        PyObject *answer = PyObject_CallMethod(search->budget, "may_store", "(n)", stored);
        Py_XDECREF(answer);
        return answer == NULL ? FAILED : STOPPED;
    }
    long depth = search->deepest = search->depth_now + 1;
    if (append_number(search->parent, frontier) < 0)
        return FAILED;
    if (*id >= search->next_checkpoint) {
        PyObject *answer = PyObject_CallMethod(search->budget, "checkpoint", "(nLi)", *id,
                                               search->transitions, (int)depth);
        if (answer == NULL)
            return FAILED;
        Py_DECREF(answer);
        search->next_checkpoint = integer_attribute(search->budget, "next_checkpoint");
        if (search->next_checkpoint < 0)
            return FAILED;
    }
    PyObject *answer = PyObject_CallOneArg(search->predicate, successor);
    if (answer == NULL)
        return FAILED;
    int bad = PyObject_IsTrue(answer);
    Py_DECREF(answer);
    if (bad)
        return bad < 0 ? FAILED : FOUND;
    int stopped = budget_stopped(search->budget);
    return stopped < 0 ? FAILED : stopped ? STOPPED : GO_ON;
}

/* Expand state ``frontier``: GO_ON, FOUND (``*target``), STOPPED or FAILED. */
static int expand_state(BreadthFirst *search, Py_ssize_t frontier, Py_ssize_t *target)
{
    PyObject *state = table_state(search->table, frontier);
    if (state == NULL)
        return FAILED;
    PyObject *successors = PyObject_CallOneArg(search->targets_of, state);
    PyObject *ids = NULL;
    int outcome = FAILED;
    if (successors == NULL)
        goto done;
    if (!PyList_CheckExact(successors) && !PyTuple_CheckExact(successors)) {
        PyErr_SetString(PyExc_TypeError, "successor_states must return a list or tuple");
        goto done;
    }
    if (search->observe != Py_None) {
        PyObject *seen = PyObject_CallFunctionObjArgs(search->observe, state, successors, NULL);
        if (seen == NULL)
            goto done;
        Py_DECREF(seen);
    }
    Py_ssize_t count = PySequence_Fast_GET_SIZE(successors);
    search->transitions += count;
    if (count == 0) {
        search->deadlocks++;
        if (search->deadlock_is_target) {
            *target = frontier;
            outcome = FOUND;
            goto done;
        }
    }
    ids = PyList_New(0);
    if (ids == NULL)
        goto done;
    for (Py_ssize_t i = 0; i < count; i++) {
        Py_ssize_t id;
        outcome = visit_successor(search, frontier, PySequence_Fast_GET_ITEM(successors, i), &id);
        if (outcome == FOUND)
            *target = id;
        if (outcome != GO_ON)
            goto done;
        PyObject *number = PyLong_FromSsize_t(id);
        if (number == NULL || PyList_Append(ids, number) < 0) {
            Py_XDECREF(number);
            outcome = FAILED;
            goto done;
        }
        Py_DECREF(number);
    }
    outcome = GO_ON;
    if (search->record != Py_None) {
        PyObject *recorded = PyObject_CallFunctionObjArgs(search->record, state, ids, NULL);
        if (recorded == NULL)
            outcome = FAILED;
        Py_XDECREF(recorded);
    }
done:
    Py_DECREF(state);
    Py_XDECREF(successors);
    Py_XDECREF(ids);
    return outcome;
}

/* depth[index] of the depth array (-1 with an error) */
static long depth_at(PyObject *depth, Py_ssize_t index)
{
    PyObject *item = PySequence_GetItem(depth, index);
    long value = item == NULL ? -1 : PyLong_AsLong(item);
    Py_XDECREF(item);
    return value;
}

/* The levels where the loop takes over: the depth of ``frontier`` and where its level
 * ends, from the depths the Python loop stored (0 or -1 with an error). */
static int find_level(BreadthFirst *search, Py_ssize_t frontier)
{
    Py_ssize_t known = PySequence_Length(search->depth);
    if (known <= frontier) {
        PyErr_SetString(PyExc_ValueError, "breadth_first: the frontier has no depth");
        return -1;
    }
    if ((search->depth_now = depth_at(search->depth, frontier)) < 0 ||
        (search->deepest = depth_at(search->depth, known - 1)) < 0)
        return -1;
    search->level_end = frontier + 1;
    while (search->level_end < known) {
        long depth = depth_at(search->depth, search->level_end);
        if (depth < 0)
            return -1;
        if (depth > search->depth_now)
            break;
        search->level_end++;
    }
    return 0;
}

static PyObject *breadth_first(PyObject *module, PyObject *args)
{
    BreadthFirst search = {0};
    Py_ssize_t frontier;
    if (!PyArg_ParseTuple(args, "O!nOOOOOOOiLL", &TableType, &search.table, &frontier,
                          &search.targets_of, &search.observe, &search.predicate,
                          &search.parent, &search.depth, &search.budget, &search.record,
                          &search.deadlock_is_target, &search.transitions, &search.deadlocks))
        return NULL;
    if (frontier >= search.table->count)
        return Py_BuildValue("(nLLl)", (Py_ssize_t)-1, search.transitions, search.deadlocks,
                             -1L);
    if (find_level(&search, frontier) < 0)
        return NULL;
    search.max_states = integer_attribute(search.budget, "max_states");
    search.next_checkpoint = integer_attribute(search.budget, "next_checkpoint");
    Py_ssize_t target = -1;
    int outcome = search.max_states < 0 || search.next_checkpoint < 0 ? FAILED : GO_ON;
    while (outcome == GO_ON && frontier < search.table->count) {
        if (frontier == search.level_end) {     /* the next level's first state */
            search.depth_now++;
            search.level_end = search.table->count;
        }
        outcome = expand_state(&search, frontier, &target);
        if (outcome == GO_ON)
            frontier++;
    }
    if (outcome == FAILED) {
        keep_counts(search.budget, search.transitions, search.deadlocks, search.deepest);
        return NULL;
    }
    return Py_BuildValue("(nLLl)", outcome == FOUND ? target : -1, search.transitions,
                         search.deadlocks, search.deepest);
}

static PyMethodDef module_functions[] = {
    {"breadth_first", breadth_first, METH_VARARGS,
     "breadth_first(table, frontier, targets_of, observe, predicate, parent, depth, budget, "
     "record, deadlock_is_target, transitions, deadlocks) -> (target id or -1, transitions, "
     "deadlocks, depth of the last stored state): reachability's loop from ``frontier`` on "
     "(see reachability.py); ``depth`` is read, not extended."},
    {NULL}
};

/* ====================================================================== module */

static struct PyModuleDef native_module = {
    PyModuleDef_HEAD_INIT,
    .m_name = "rapidmc.check._native",
    .m_doc = "The compiled search core of rapidmc (see rapidmc/check/native.py).",
    .m_size = -1,
    .m_methods = module_functions,
};

PyMODINIT_FUNC PyInit__native(void)
{
    if (PyType_Ready(&TableType) < 0 || PyType_Ready(&CycleSearchType) < 0)
        return NULL;
    PyObject *module = PyModule_Create(&native_module);
    if (module == NULL)
        return NULL;
    Py_INCREF(&TableType);
    Py_INCREF(&CycleSearchType);
    if (PyModule_AddObject(module, "Table", (PyObject *)&TableType) < 0 ||
        PyModule_AddObject(module, "CycleSearch", (PyObject *)&CycleSearchType) < 0 ||
        PyModule_AddIntConstant(module, "VERSION", 2) < 0 || packed_register(module) < 0 ||
        nodes_register(module) < 0) {
        Py_DECREF(module);
        return NULL;
    }
    return module;
}
