/* Packed states and the step machine: the search's hot loop without Python objects.
 *
 * A model that can describe its states as two vectors of small numbers (rapidmc's
 * RAPID model does, see rapidmc/model/packed/) hands the search a ``PackedTable``:
 *
 * - values: every distinct value a state holds gets an id (numbers and booleans by
 *   value, ``-0.0`` with ``0.0`` as Python's ``==`` has it; other objects through a
 *   dict), so a state is vectors of 32-bit value ids;
 * - segments: a state is a frame vector (context id, program counter, local data) and
 *   a data vector (global data), each interned once in a table of its own
 *   (SPIN's collapse compression), and the state is the pair of segment ids, interned in
 *   an open-addressing table: ids in the order states were first interned, as the Python
 *   table gives them; a context (what the fused step never changes, signals included)
 *   is numbered by the model, which tells the machine what it needs of one;
 * - the step machine: a routine's fused steps (``semantics/fused_step.py``) compiled to a
 *   small stack code (``model/packed/bytecode.py``) that runs on the vectors.  Whatever
 *   the code does not cover (calls, errors, strings, handlers...) makes it give up
 *   before it changes anything; the search then asks the Python step for that state.
 *   Property atoms are compiled the same way (an error makes an atom false, as in
 *   ``model/fused_atoms.py``).  With several tasks (``tasks_step``) the frame vector holds
 *   each running task's top frame; the machine steps each task's instruction it can and
 *   asks Python for the others' alone, then drops idle steps as ``staged_step`` does.
 *
 * ``packed_breadth_first`` is reachability.py's unlabelled loop over such a table: the
 * same states, ids, transitions, deadlocks and rows of the explored graph, and the same
 * Python calls for the states the step machine leaves to Python.
 */
#include "_common.h"
#include <math.h>

enum { T_NUM = 0, T_BOOL = 1, T_INT = 2, T_OBJ = 3 };

/* what a context says (model/packed/table.py): the machine may step there; the program
 * has failed there */
enum { CONTEXT_RUNS = 1, CONTEXT_FAILED = 2, CONTEXT_MAIN_ALONE = 4, CONTEXT_ENDED_TASK = 8 };
/* what a context says of one of several tasks: the machine may step its top frame */
enum { TASK_RUNS = 1 };
/* what the partial-order reduction says of a task's instruction (model/packed/table.py's
 * ``_order_flags``): independent and invisible (an ample candidate); its step always
 * changes the state; it joins the step of its task before it (a merged local run) */
enum { ORDER_CANDIDATE = 1, ORDER_NEVER_WAITS = 2, ORDER_MERGEABLE = 4, ORDER_GROUPS = 8,
       ORDER_HELD = 16 };

/* opcodes of the step machine (mirrored in rapidmc/model/packed/bytecode.py) */
enum {
    OP_CONST = 1, OP_LOAD_STORE, OP_LOAD_LOCAL, OP_READ, OP_READ_DYN,
    OP_ADD, OP_SUB, OP_MUL, OP_DIVIDE, OP_TO_NUM, OP_TO_DNUM, OP_INT_DIV, OP_INT_MOD,
    OP_NEG, OP_NOT, OP_EQ, OP_NE, OP_LT, OP_LE, OP_GT, OP_GE, OP_AND, OP_OR,
    OP_SET_STORE, OP_SET_LOCAL, OP_SET_TEMP, OP_GET_TEMP,
    OP_GOTO, OP_BRANCH, OP_GOTO_IF, OP_RESET_CHOSEN, OP_UNSUPPORTED,
    OP_FOR_DEFAULT_STEP, OP_FOR_INIT, OP_FOR_NEXT,
    OP_ATOM_BEGIN, OP_ATOM_END, OP_END,
    OP_TASK_ONLY, OP_JUMP_IF_FALSE, OP_REQUIRE, OP_POP, OP_CHOOSE_BOOL, OP_WAIT, OP_SYNC,
    OP_CHOOSE_CONST, OP_CHECK_INDEX, OP_SET_ELEMENT, OP_BUILD_TUPLE, OP_CALL, OP_LEAVE
};

/* a step that changes the task's frames (``Run.frame_op``): a call, a procedure's end */
enum { FRAME_KEPT = 0, FRAME_CALL = 1, FRAME_LEAVE = 2 };

/* what a run of code ends with */
enum { VM_DONE = 0, VM_ERROR = 1, VM_UNSUPPORTED = 2 };

#define FRAME_CACHE 1024
#define ID_CACHE 4096           /* objects found by identity before the dict (value_id) */
#define TASK_INFO 4             /* per task of a context: routine, where, locals, flags */
#define TASK_COUNT_MAX 64
#define STACK_SIZE 64
#define TEMPS 8
#define MAX_CHOICES 64
#define MAX_BLOCKS_PER_STEP 100000
#define NUM_EXACT_INTEGER 8388608.0
#define INT_LIMIT 4611686018427387904.0        /* 2**62: integer operands beyond it: Python */
#define SYNC_ARRIVED 10.0       /* library/tasks.py's ARRIVED: a task waits at the barrier */

typedef struct {
    int tag;
    double d;           /* T_NUM, T_BOOL (0/1), T_INT */
    int32_t id;         /* the value's id, -1 while not interned (numbers computed here) */
} Value;

#define DECODED 4       /* a narrow table's vectors read out at once, at most (``vt_read``) */

/* ``reserve`` for a compact table's arrays (``compact``): grown by an eighth, not a half,
 * so at most a ninth of their room is spare (a large block's growth moves no bytes: the C
 * library remaps its pages) */
static void *reserve_gently(void *items, Py_ssize_t *capacity, size_t size, Py_ssize_t wanted)
{
    return reserve_by(items, capacity, size, wanted, 8);
}

typedef struct {        /* a table of vectors of value ids, each stored once */
    uint32_t *arena;    /* (``width`` bytes an item: 1 and 2 as uint8_t, uint16_t) */
    Py_ssize_t arena_length, arena_capacity;
    int64_t *offsets;   /* vector i: arena[offsets[i] .. offsets[i + 1]) */
    Py_ssize_t count, offsets_capacity;
    uint32_t *hashes;   /* by id: the vector's hash (compared before its items) */
    Py_ssize_t hashes_capacity;
    int32_t *slots;
    uint64_t mask;
    /* a compact table's data segments (``compact``) keep each item in the fewest bytes
     * that hold every id stored so far (1, 2 or 4), widened when one does not fit; such a
     * table's vectors are read out into ``decoded`` buffers, in turn (``vt_read``), each
     * room for the longest vector */
    int width;
    uint32_t *decoded[DECODED];
    Py_ssize_t longest;
    int next_decoded;
} VectorTable;

typedef struct {        /* one routine's compiled steps */
    Py_ssize_t length;          /* instructions */
    uint8_t *kinds, *first_visible;
    int32_t *block_start;       /* per pc: where its block starts in ``code``, -1: none */
    int32_t *code;
    Py_ssize_t code_length;
    /* the projection's resets of local data at each pc: (slot, value id) pairs
     * reset_pairs[2 * reset_offsets[pc] .. 2 * reset_offsets[pc + 1]) */
    int32_t *reset_offsets, *reset_pairs;
    uint8_t *executed;          /* per pc: 1 once a step the machine took ran it */
} Routine;

typedef struct {        /* resets of global data: one list, or one per pc of main */
    int32_t *offsets, *pairs;
    Py_ssize_t lists;
} Resets;

/* a set of states by key (frame id << 32 | data id), each with its id, the order it came
 * in: a search's stored states (the table's own, or a ``StateSet``'s: one per search of a
 * check, ``new_states``), or the numbering of the reduction's cycle proviso (``places``) */
typedef struct {
    int64_t *keys;              /* by id (``narrow``: uint32_t each, ``index_key``) */
    Py_ssize_t count, key_capacity;
    int32_t *slots;             /* the hash index (NULL: released, made again when asked) */
    uint64_t mask;
    int narrow;                 /* keys in 4 bytes while they fit (``compact``) */
} StateIndex;

typedef struct {        /* compiled atoms of one valuation */
    int32_t *code;
    Py_ssize_t code_length;
} Valuation;

typedef struct {
    PyObject_HEAD
    /* values by id */
    uint8_t *value_tag;
    double *value_number;
    PyObject **value_object;    /* the Python object (made when first asked for numbers) */
    Py_ssize_t values, value_capacity;
    int32_t *value_slots;       /* numbers and booleans: (tag, value) -> id */
    uint64_t value_mask;
    PyObject *object_ids;       /* other objects: object -> id */
    /* other objects met lately, by address (each held, so no other object takes its
     * address while it is here): a state rebuilt from the table hands on the table's own
     * objects, and hashing a 512-element array again costs what the lookup saves */
    PyObject *id_cache_object[ID_CACHE];
    int32_t id_cache_id[ID_CACHE];
    /* tuples of BIG_TUPLE items or more (arrays): found by a hash of their items' hashes,
     * each item's hash remembered by address (held, as above), so a new array that shares
     * most items with one met before (an element written) is hashed in one pass over
     * addresses, not element by element down to the numbers; equal by ``==`` as the dict's */
    PyObject **item_memo_object;
    Py_hash_t *item_memo_hash;
    int32_t *big_slots;         /* -> value id (EMPTY: free), with the tuple's hash */
    uint64_t *big_hashes;
    /* by value id, of a big tuple: the sum of its items' parts (``big_part``), from which
     * its hash is made, so that a tuple with one item replaced is hashed in one step */
    uint64_t *big_sums;
    Py_ssize_t big_sums_capacity;
    uint64_t big_mask;
    Py_ssize_t big_count;
    /* segments and states (``states``: the selected search's, see ``selected`` below) */
    VectorTable frames, data;
    /* a distributed worker's spare data segments (``spare_data``): those its steps made in
     * this round that ``data`` does not hold, numbered SPARE | index */
    VectorTable spare;
    int sparing;
    /* a distributed worker's table (``compact``): narrow state keys and data segments */
    int compact;
    StateIndex states;
    /* contexts (by context id): the routine of the top frame (-1: none), whether the
     * step machine may run there */
    int32_t *context_routine;
    uint8_t *context_runs;      /* CONTEXT_ flags */
    /* several tasks: per context, TASK_INFO numbers per task (``task_info``): the routine
     * of its top frame (-1: the task has ended), where its pc is in the frame vector, how
     * many local values follow, TASK_ flags */
    Py_ssize_t task_count;
    int32_t *context_tasks;
    Py_ssize_t context_tasks_capacity;      /* (in contexts) */
    int32_t *context_io;        /* the signals' values: a vector of ``signals`` */
    VectorTable signals;
    Py_ssize_t contexts, context_capacity;
    /* the program */
    Routine *routines;
    Py_ssize_t routine_count;
    Py_ssize_t store_length, io_length;
    int32_t **lazy_domain;      /* by signal index: the domain's value ids, NULL: not lazy */
    int32_t *lazy_size;
    Valuation *valuations;
    Py_ssize_t valuation_count;
    /* the projection the model applies to the fused step's targets (None: none) */
    int projecting;
    Resets global_resets, main_resets;
    /* (routine, pc) pairs run for the first time by steps the machine took */
    Int32Vector newly_executed;
    struct Scratch *scratch;    /* the machine's scratch space for ``successor_ids`` */
    /* (frame id, pc) + 1 -> frame id: the frames a step reaches without changing locals */
    uint64_t frame_cache_key[FRAME_CACHE];
    int32_t frame_cache_value[FRAME_CACHE];
    /* counters: states stepped by the machine / by Python; with several tasks, also the
     * steps of single tasks within a state taken by each */
    long long machine_steps, python_steps, task_machine_steps, task_python_steps;
    /* the search's observer still wants the lines steps run: Python's steps of single
     * tasks then tell it theirs (``note_python_spans``) */
    int labels_wanted;
    /* the partial-order reduction (``set_order``): per (task, routine) the ORDER_ flags of
     * each pc, order_flags[order_offsets[task * order_routines + routine] + pc] (offset -1:
     * none); ``reduced``: steps of several tasks keep the ample set of one task */
    uint8_t *order_flags;
    int64_t *order_offsets;
    int64_t *order_lengths;
    Py_ssize_t order_routines;
    int reduced;
    /* the searches of one check share the table (values, segments, contexts, the program):
     * each stores its states in a ``StateSet`` of its own, whose index is in the fields
     * above (keys ... mask) while it is ``selected`` (NULL: the table's ``own`` is) */
    PyObject *selected;
    StateIndex own;
    /* the reduction's numbering of states (``PartialOrder``'s C3): every search's */
    StateIndex places;
    /* the successors of the reduced steps by the state's number, kept for the check's
     * later searches (a state's ample set is the same whenever asked): row_at[place] is
     * its row's count of successors (above ROW_OFFSET_BITS) and where their keys start in
     * row_keys, -1: none */
    int64_t *row_at;
    Py_ssize_t row_at_capacity;
    int64_t *row_keys;
    Py_ssize_t row_length, row_capacity;
    long long rows_reused;
    /* calls and returns the machine's local runs went on through (``run_on``) */
    long long run_frame_steps;
    /* what Python answered ``frame_step`` (``entered_context``), kept: per question (a
     * vector of ``frame_questions``: FRAME_CALL, context, task, pc, callee, the caller's
     * locals; or FRAME_LEAVE, context, task) the id of its answer in ``frame_answers``
     * (entered context, pc, the caller's locals), NO_ANSWER where Python steps it */
    VectorTable frame_questions, frame_answers;
    Int32Vector answer_of;
} PackedTable;

#define NO_ANSWER (-1)

typedef struct {
    PyObject_HEAD
    StateIndex index;           /* (while selected, the table's fields hold it) */
} StateSet;

/* ================================================================ vector tables */

static inline uint64_t hash_vector(const uint32_t *items, Py_ssize_t length)
{
    uint64_t h = (uint64_t)length * 0x9e3779b97f4a7c15ULL;
    Py_ssize_t i = 0;
    for (; i + 1 < length; i += 2) {        /* two ids per multiplication */
        h = (h ^ (items[i] | (uint64_t)items[i + 1] << 32)) * 0xff51afd7ed558ccdULL;
        h ^= h >> 29;
    }
    if (i < length) {
        h = (h ^ items[i]) * 0xff51afd7ed558ccdULL;
        h ^= h >> 29;
    }
    return mix64(h);
}

static inline int same_items(const uint32_t *a, const uint32_t *b, Py_ssize_t length)
{
    for (Py_ssize_t i = 0; i < length; i++)
        if (a[i] != b[i])
            return 0;
    return 1;
}

static int vt_init(VectorTable *table)
{
    table->width = 4;
    table->slots = new_slots(FIRST_CAPACITY);
    table->offsets = PyMem_Malloc(256 * sizeof(int64_t));
    if (table->slots == NULL || table->offsets == NULL) {
        if (!PyErr_Occurred())
            PyErr_NoMemory();
        return -1;
    }
    table->mask = FIRST_CAPACITY - 1;
    table->offsets_capacity = 256;
    table->offsets[0] = 0;
    return 0;
}

static void vt_free(VectorTable *table)
{
    for (int i = 0; i < DECODED; i++)
        PyMem_Free(table->decoded[i]);
    PyMem_Free(table->arena);
    PyMem_Free(table->offsets);
    PyMem_Free(table->slots);
    PyMem_Free(table->hashes);
}

static inline const uint32_t *vt_items(const VectorTable *table, int32_t id, Py_ssize_t *length)
{
    *length = (Py_ssize_t)(table->offsets[id + 1] - table->offsets[id]);
    return table->arena + table->offsets[id];
}

static inline uint32_t vt_item_at(const VectorTable *table, int64_t at)
{
    switch (table->width) {
    case 1: return ((const uint8_t *)table->arena)[at];
    case 2: return ((const uint16_t *)table->arena)[at];
    default: return table->arena[at];
    }
}

/* the items of vector ``id`` of any width, as uint32_t: a table of width 4 hands out its
 * arena, a narrow one the next of its ``decoded`` buffers (valid until DECODED more
 * vectors are read out of it) */
static const uint32_t *vt_read(VectorTable *table, int32_t id, Py_ssize_t *length)
{
    if (table->width == 4)
        return vt_items(table, id, length);
    int64_t from = table->offsets[id];
    *length = (Py_ssize_t)(table->offsets[id + 1] - from);
    uint32_t *out = table->decoded[table->next_decoded];
    table->next_decoded = (table->next_decoded + 1) % DECODED;
    for (Py_ssize_t i = 0; i < *length; i++)
        out[i] = vt_item_at(table, from + i);
    return out;
}

static int vt_same(const VectorTable *table, int32_t id, const uint32_t *items,
                   Py_ssize_t length)
{
    int64_t from = table->offsets[id];
    if ((Py_ssize_t)(table->offsets[id + 1] - from) != length)
        return 0;
    if (table->width == 4)
        return same_items(table->arena + from, items, length);
    for (Py_ssize_t i = 0; i < length; i++)
        if (vt_item_at(table, from + i) != items[i])
            return 0;
    return 1;
}

/* the fewest bytes (1, 2, 4) an item takes to hold every one of ``items`` */
static int width_for(const uint32_t *items, Py_ssize_t length)
{
    uint32_t largest = 0;
    for (Py_ssize_t i = 0; i < length; i++)
        largest |= items[i];
    return largest < (1u << 8) ? 1 : largest < (1u << 16) ? 2 : 4;
}

/* room in each ``decoded`` buffer for a vector of ``length`` items (a narrow table); -1 */
static int vt_room(VectorTable *table, Py_ssize_t length)
{
    if (table->width == 4 || length <= table->longest)
        return 0;
    for (int i = 0; i < DECODED; i++) {
        uint32_t *grown = PyMem_Realloc(table->decoded[i], length * sizeof(uint32_t));
        if (grown == NULL) {
            PyErr_NoMemory();
            return -1;
        }
        table->decoded[i] = grown;
    }
    table->longest = length;
    return 0;
}

/* the table's items in ``width`` bytes each from now on (every stored one must fit); -1 */
static int vt_set_width(VectorTable *table, int width)
{
    if (width == table->width)
        return 0;
    Py_ssize_t capacity = table->arena_capacity;
    void *arena = PyMem_Malloc((capacity ? capacity : 1) * width);
    if (arena == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    for (Py_ssize_t at = 0; at < table->arena_length; at++) {
        uint32_t item = vt_item_at(table, at);
        if (width == 1)
            ((uint8_t *)arena)[at] = (uint8_t)item;
        else if (width == 2)
            ((uint16_t *)arena)[at] = (uint16_t)item;
        else
            ((uint32_t *)arena)[at] = item;
    }
    PyMem_Free(table->arena);
    table->arena = arena;
    table->width = width;
    Py_ssize_t longest = 0;
    for (Py_ssize_t id = 0; id < table->count; id++)
        if (table->offsets[id + 1] - table->offsets[id] > longest)
            longest = (Py_ssize_t)(table->offsets[id + 1] - table->offsets[id]);
    table->longest = 0;
    return vt_room(table, longest > 0 ? longest : 1);
}

/* a compact table: the items in the fewest bytes that hold them all (``width``); -1 */
static int vt_narrow(VectorTable *table)
{
    if (table->width < 4)
        return 0;
    int width = width_for(table->arena, table->arena_length);
    return width < 4 ? vt_set_width(table, width) : 0;
}

static int vt_grow(VectorTable *table)
{
    uint64_t capacity = (table->mask + 1) * 2;
    int32_t *slots = new_slots(capacity);
    if (slots == NULL)
        return -1;
    for (Py_ssize_t id = 0; id < table->count; id++) {
        uint64_t position = mix64(table->hashes[id]) & (capacity - 1);
        while (slots[position] != EMPTY)
            position = (position + 1) & (capacity - 1);
        slots[position] = (int32_t)id;
    }
    PyMem_Free(table->slots);
    table->slots = slots;
    table->mask = capacity - 1;
    return 0;
}

/* the id of the vector ``items`` (hashed ``hash``) in ``table``, else -1 with ``*position``
 * the free slot where it would go */
static int32_t vt_probe(const VectorTable *table, const uint32_t *items, Py_ssize_t length,
                        uint32_t hash, uint64_t *position)
{
    uint64_t at = mix64(hash) & table->mask;
    for (;;) {
        int32_t id = table->slots[at];
        if (id == EMPTY)
            break;
        if (table->hashes[id] == hash && vt_same(table, id, items, length))
            return id;
        at = (at + 1) & table->mask;
    }
    *position = at;
    return -1;
}

/* the id of the vector ``items`` (stored when new); -1 with an error */
static int32_t vt_intern(VectorTable *table, const uint32_t *items, Py_ssize_t length)
{
    uint32_t hash = (uint32_t)hash_vector(items, length);
    uint64_t position = 0;
    int32_t found = vt_probe(table, items, length, hash, &position);
    if (found >= 0)
        return found;
    if (table->count >= INT32_MAX - 1) {
        PyErr_SetString(PyExc_OverflowError, "more than 2**31 distinct state parts");
        return -1;
    }
    if (table->width < 4) {
        int width = width_for(items, length);
        if ((width > table->width && vt_set_width(table, width) < 0) ||
                vt_room(table, length) < 0)
            return -1;
    }
    void *(*grow)(void *, Py_ssize_t *, size_t, Py_ssize_t) =
        table->width < 4 ? reserve_gently : reserve;
    uint32_t *arena = grow(table->arena, &table->arena_capacity, table->width,
                           table->arena_length + length + 1);
    if (arena == NULL)
        return -1;
    table->arena = arena;
    int64_t *offsets = grow(table->offsets, &table->offsets_capacity, sizeof(int64_t),
                            table->count + 2);
    if (offsets == NULL)
        return -1;
    table->offsets = offsets;
    uint32_t *hashes = grow(table->hashes, &table->hashes_capacity, sizeof(uint32_t),
                            table->count + 1);
    if (hashes == NULL)
        return -1;
    table->hashes = hashes;
    if (table->width == 4)
        memcpy(table->arena + table->arena_length, items, length * sizeof(uint32_t));
    else if (table->width == 2)
        for (Py_ssize_t i = 0; i < length; i++)
            ((uint16_t *)table->arena)[table->arena_length + i] = (uint16_t)items[i];
    else
        for (Py_ssize_t i = 0; i < length; i++)
            ((uint8_t *)table->arena)[table->arena_length + i] = (uint8_t)items[i];
    table->arena_length += length;
    int32_t id = (int32_t)table->count++;
    table->offsets[id + 1] = table->arena_length;
    table->hashes[id] = hash;
    table->slots[position] = id;
    if ((uint64_t)table->count * 2 > table->mask + 1 && vt_grow(table) < 0)
        return -1;
    return id;
}

/* drop the index (slots) of a table whose vectors stay; ``vt_index`` makes it again */
static void vt_release_index(VectorTable *table)
{
    PyMem_Free(table->slots);
    table->slots = NULL;
}

static int vt_index(VectorTable *table)
{
    if (table->slots != NULL)
        return 0;
    uint64_t capacity = FIRST_CAPACITY;
    while ((uint64_t)table->count * 2 > capacity)
        capacity *= 2;
    table->slots = new_slots(capacity);
    if (table->slots == NULL)
        return -1;
    for (Py_ssize_t id = 0; id < table->count; id++) {
        uint64_t position = mix64(table->hashes[id]) & (capacity - 1);
        while (table->slots[position] != EMPTY)
            position = (position + 1) & (capacity - 1);
        table->slots[position] = (int32_t)id;
    }
    table->mask = capacity - 1;
    return 0;
}

static Py_ssize_t vt_bytes(const VectorTable *table)
{
    return table->arena_capacity * table->width + table->offsets_capacity * sizeof(int64_t)
        + (table->width < 4 ? DECODED * table->longest * (Py_ssize_t)sizeof(uint32_t) : 0)
        + table->hashes_capacity * sizeof(uint32_t) +
        (table->slots != NULL ? (table->mask + 1) * sizeof(int32_t) : 0);
}

/* the id of the vector ``items`` in ``table``, -1 when it holds none such */
static int32_t vt_find(const VectorTable *table, const uint32_t *items, Py_ssize_t length)
{
    uint64_t position;
    return vt_probe(table, items, length, (uint32_t)hash_vector(items, length), &position);
}

/* ======================================================================= values */

static uint64_t number_key(int tag, double d)
{
    if (d == 0.0)
        d = 0.0;                /* -0.0 == 0.0, as Python compares them */
    uint64_t bits;
    memcpy(&bits, &d, sizeof bits);
    return mix64(bits ^ ((uint64_t)tag << 61) ^ 0x5851f42d4c957f2dULL);
}

static int same_number(PackedTable *self, int32_t id, int tag, double d)
{
    if (self->value_tag[id] != tag)
        return 0;
    double stored = self->value_number[id];
    if (stored == d)
        return 1;
    return stored != stored && d != d &&
        memcmp(&stored, &d, sizeof d) == 0;         /* the same NaN */
}

static int grow_values(PackedTable *self)
{
    uint64_t capacity = (self->value_mask + 1) * 2;
    int32_t *slots = new_slots(capacity);
    if (slots == NULL)
        return -1;
    for (Py_ssize_t id = 0; id < self->values; id++) {
        if (self->value_tag[id] == T_OBJ)
            continue;
        uint64_t position = number_key(self->value_tag[id], self->value_number[id]) &
            (capacity - 1);
        while (slots[position] != EMPTY)
            position = (position + 1) & (capacity - 1);
        slots[position] = (int32_t)id;
    }
    PyMem_Free(self->value_slots);
    self->value_slots = slots;
    self->value_mask = capacity - 1;
    return 0;
}

/* a new value id (its object may be NULL: made when asked for); -1 with an error */
static int32_t add_value(PackedTable *self, int tag, double d, PyObject *object)
{
    Py_ssize_t capacity = self->value_capacity;
    uint8_t *tags = reserve(self->value_tag, &capacity, 1, self->values + 1);
    if (tags == NULL)
        return -1;
    self->value_tag = tags;
    capacity = self->value_capacity;
    double *numbers = reserve(self->value_number, &capacity, sizeof(double), self->values + 1);
    if (numbers == NULL)
        return -1;
    self->value_number = numbers;
    capacity = self->value_capacity;
    PyObject **objects = reserve(self->value_object, &capacity, sizeof(PyObject *),
                                 self->values + 1);
    if (objects == NULL)
        return -1;
    self->value_object = objects;
    self->value_capacity = capacity;
    int32_t id = (int32_t)self->values++;
    self->value_tag[id] = (uint8_t)tag;
    self->value_number[id] = d;
    Py_XINCREF(object);
    self->value_object[id] = object;
    return id;
}

/* the id of a number or boolean (stored when new, with ``object`` if given) */
static int32_t number_id(PackedTable *self, int tag, double d, PyObject *object)
{
    uint64_t position = number_key(tag, d) & self->value_mask;
    for (;;) {
        int32_t id = self->value_slots[position];
        if (id == EMPTY)
            break;
        if (same_number(self, id, tag, d))
            return id;
        position = (position + 1) & self->value_mask;
    }
    int32_t id = add_value(self, tag, d, object);
    if (id < 0)
        return -1;
    self->value_slots[position] = id;
    if ((uint64_t)self->values * 2 > self->value_mask + 1 && grow_values(self) < 0)
        return -1;
    return id;
}

#define BIG_TUPLE 32             /* tuples at least this long: ``big_tuple_id`` */
#define ITEM_MEMO 16384          /* items' hashes remembered by address */

/* The hash of ``item`` as an item of a big tuple: a tuple's remembered by address (held,
 * so that no other object takes the address while it is remembered).  0 or -1. */
static int big_item_hash(PackedTable *self, PyObject *item, Py_hash_t *out)
{
    if (!PyTuple_Check(item))
        return (*out = PyObject_Hash(item)) == -1 ? -1 : 0;
    if (self->item_memo_object == NULL) {
        self->item_memo_object = PyMem_Calloc(ITEM_MEMO, sizeof(PyObject *));
        self->item_memo_hash = PyMem_Calloc(ITEM_MEMO, sizeof(Py_hash_t));
        if (self->item_memo_object == NULL || self->item_memo_hash == NULL) {
            PyErr_NoMemory();
            return -1;
        }
    }
    uint64_t at = mix64((uint64_t)(uintptr_t)item) & (ITEM_MEMO - 1);
    if (self->item_memo_object[at] == item) {
        *out = self->item_memo_hash[at];
        return 0;
    }
    Py_hash_t hash = PyObject_Hash(item);
    if (hash == -1)
        return -1;
    Py_INCREF(item);
    Py_XSETREF(self->item_memo_object[at], item);
    self->item_memo_hash[at] = hash;
    *out = hash;
    return 0;
}

/* item ``index``'s part (its hash ``hash``) in the sum a big tuple's hash is made of: a sum,
 * so that replacing one item changes it by two parts */
static inline uint64_t big_part(Py_ssize_t index, Py_hash_t hash)
{
    return mix64((uint64_t)hash + (uint64_t)index * 0x9e3779b97f4a7c15ULL);
}

/* the hash of a big tuple of ``length`` items whose parts sum to ``sum`` */
static inline uint64_t big_key(uint64_t sum, Py_ssize_t length)
{
    return mix64(sum ^ (uint64_t)length);
}

/* the sum of a big tuple's parts (equal tuples: equal items, equal sums), -1 with an
 * error */
static int big_tuple_sum(PackedTable *self, PyObject *tuple, uint64_t *out)
{
    uint64_t sum = 0;
    for (Py_ssize_t i = 0; i < PyTuple_GET_SIZE(tuple); i++) {
        Py_hash_t item_hash;
        if (big_item_hash(self, PyTuple_GET_ITEM(tuple, i), &item_hash) < 0)
            return -1;
        sum += big_part(i, item_hash);
    }
    *out = sum;
    return 0;
}

static int big_grow(PackedTable *self)
{
    uint64_t capacity = self->big_slots == NULL ? 1024 : (self->big_mask + 1) * 2;
    int32_t *slots = new_slots((Py_ssize_t)capacity);
    uint64_t *hashes = slots == NULL ? NULL : PyMem_Malloc(capacity * sizeof(uint64_t));
    if (hashes == NULL) {
        PyMem_Free(slots);
        return PyErr_Occurred() ? -1 : (PyErr_NoMemory(), -1);
    }
    for (uint64_t i = 0; self->big_slots != NULL && i <= self->big_mask; i++) {
        if (self->big_slots[i] == EMPTY)
            continue;
        uint64_t at = self->big_hashes[i] & (capacity - 1);
        while (slots[at] != EMPTY)
            at = (at + 1) & (capacity - 1);
        slots[at] = self->big_slots[i];
        hashes[at] = self->big_hashes[i];
    }
    PyMem_Free(self->big_slots);
    PyMem_Free(self->big_hashes);
    self->big_slots = slots;
    self->big_hashes = hashes;
    self->big_mask = capacity - 1;
    return 0;
}

/* Whether ``stored`` equals ``base`` with item ``index`` replaced by ``item`` (``item``
 * NULL: ``base`` itself), item by item as ``==`` compares tuples: 1, 0, -1 */
static int big_equal(PyObject *stored, PyObject *base, Py_ssize_t index, PyObject *item)
{
    Py_ssize_t length = PyTuple_GET_SIZE(base);
    if (!PyTuple_Check(stored) || PyTuple_GET_SIZE(stored) != length)
        return 0;
    for (Py_ssize_t i = 0; i < length; i++) {
        PyObject *mine = item != NULL && i == index ? item : PyTuple_GET_ITEM(base, i);
        PyObject *theirs = PyTuple_GET_ITEM(stored, i);
        if (mine == theirs)
            continue;
        int same = PyObject_RichCompareBool(mine, theirs, Py_EQ);
        if (same <= 0)
            return same;
    }
    return 1;
}

static PyObject *replaced_at(PyObject *value, const int32_t *path, int32_t depth,
                             PyObject *item);

/* The id of the tuple of BIG_TUPLE items or more that is ``base`` with item ``index``
 * replaced by ``item`` (``item`` NULL: ``base`` itself), whose items' parts sum to
 * ``sum``; stored when new (the tuple made then).  -1 with an error. */
static int32_t big_tuple_find(PackedTable *self, PyObject *base, Py_ssize_t index,
                              PyObject *item, uint64_t sum)
{
    if (self->big_slots == NULL && big_grow(self) < 0)
        return -1;
    uint64_t hash = big_key(sum, PyTuple_GET_SIZE(base));
    uint64_t at = hash & self->big_mask;
    for (;;) {
        int32_t id = self->big_slots[at];
        if (id == EMPTY)
            break;
        if (self->big_hashes[at] == hash) {
            int same = big_equal(self->value_object[id], base, index, item);
            if (same < 0)
                return -1;
            if (same)
                return id;
        }
        at = (at + 1) & self->big_mask;
    }
    int32_t path = (int32_t)index;
    PyObject *tuple = item == NULL ? Py_NewRef(base) : replaced_at(base, &path, 1, item);
    if (tuple == NULL)
        return -1;
    int32_t id = add_value(self, T_OBJ, 0.0, tuple);
    Py_DECREF(tuple);                           /* (the table holds it) */
    if (id < 0)
        return -1;
    uint64_t *sums = reserve(self->big_sums, &self->big_sums_capacity, sizeof(uint64_t),
                             id + 1);
    if (sums == NULL)
        return -1;
    self->big_sums = sums;
    self->big_sums[id] = sum;
    self->big_slots[at] = id;
    self->big_hashes[at] = hash;
    if ((uint64_t)++self->big_count * 2 > self->big_mask + 1 && big_grow(self) < 0)
        return -1;
    return id;
}

/* the id of a tuple of BIG_TUPLE items or more (stored when new); -1 with an error */
static int32_t big_tuple_id(PackedTable *self, PyObject *tuple)
{
    uint64_t sum;
    return big_tuple_sum(self, tuple, &sum) < 0 ? -1 : big_tuple_find(self, tuple, 0, NULL, sum);
}

/* The id of the big tuple ``array`` (id ``array_id``) with item ``index`` replaced by
 * ``item``, its sum changed by that item's two parts: the cost of a write of one element
 * of a 512-element array does not grow with the array, and no tuple is made where the
 * table holds it already.  -1 with an error. */
static int32_t big_replaced_id(PackedTable *self, int32_t array_id, PyObject *array,
                               Py_ssize_t index, PyObject *item)
{
    Py_hash_t before, after;
    if (big_item_hash(self, PyTuple_GET_ITEM(array, index), &before) < 0 ||
            big_item_hash(self, item, &after) < 0)
        return -1;
    uint64_t sum = self->big_sums[array_id] - big_part(index, before) + big_part(index, after);
    return big_tuple_find(self, array, index, item, sum);
}

/* the id of any Python value; -1 with an error */
static int32_t value_id(PackedTable *self, PyObject *object)
{
    PyTypeObject *type = Py_TYPE(object);
    if (type == &PyFloat_Type)
        return number_id(self, T_NUM, PyFloat_AS_DOUBLE(object), object);
    if (type == &PyBool_Type)
        return number_id(self, T_BOOL, object == Py_True ? 1.0 : 0.0, object);
    if (type == &PyLong_Type) {
        int overflow = 0;
        long long number = PyLong_AsLongLongAndOverflow(object, &overflow);
        if (number == -1 && PyErr_Occurred())
            return -1;
        if (!overflow && number > -(1LL << 53) && number < (1LL << 53))
            return number_id(self, T_INT, (double)number, object);
    }
    uint64_t cached = mix64((uint64_t)(uintptr_t)object) & (ID_CACHE - 1);
    if (self->id_cache_object[cached] == object)
        return self->id_cache_id[cached];
    int32_t id;
    PyObject *known = NULL;
    if (PyTuple_Check(object) && PyTuple_GET_SIZE(object) >= BIG_TUPLE) {
        if ((id = big_tuple_id(self, object)) < 0)
            return -1;
    }
    else if ((known = PyDict_GetItemWithError(self->object_ids, object)) != NULL)
        id = (int32_t)PyLong_AsLong(known);
    else {
        if (PyErr_Occurred())
            return -1;
        id = add_value(self, T_OBJ, 0.0, object);
        if (id < 0)
            return -1;
        PyObject *number = PyLong_FromLong(id);
        if (number == NULL || PyDict_SetItem(self->object_ids, object, number) < 0) {
            Py_XDECREF(number);
            return -1;
        }
        Py_DECREF(number);
    }
    if (type == &PyTuple_Type) {        /* (what is costly to hash: arrays, records) */
        Py_INCREF(object);
        Py_XSETREF(self->id_cache_object[cached], object);
        self->id_cache_id[cached] = id;
    }
    return id;
}

/* the Python object of a value id (a new reference) */
static PyObject *value_object(PackedTable *self, int32_t id)
{
    PyObject *object = self->value_object[id];
    if (object == NULL) {
        double d = self->value_number[id];
        switch (self->value_tag[id]) {
        case T_NUM: object = PyFloat_FromDouble(d); break;
        case T_BOOL: object = PyBool_FromLong(d != 0.0); break;
        default: object = PyLong_FromLongLong((long long)d); break;
        }
        if (object == NULL)
            return NULL;
        self->value_object[id] = object;
    }
    Py_INCREF(object);
    return object;
}

/* ======================================================================== states */

/* A compact table's state keys (``compact``) are 4 bytes while the frame id is below
 * 2**(32 - NARROW_DATA_BITS) and the data id below 2**NARROW_DATA_BITS: a distributed
 * worker's table then costs 4 bytes a state less (and a third of its keys' spare room
 * less).  A key that does not fit widens the whole array to 8 bytes a key, once. */
#define NARROW_DATA_BITS 24
#define NARROW_DATA_MASK ((1u << NARROW_DATA_BITS) - 1)

static inline int64_t index_key(const StateIndex *index, Py_ssize_t id)
{
    if (!index->narrow)
        return index->keys[id];
    uint32_t narrow = ((const uint32_t *)index->keys)[id];
    return ((int64_t)(narrow >> NARROW_DATA_BITS) << 32) | (narrow & NARROW_DATA_MASK);
}

static inline int narrow_fits(int64_t key)
{
    return (uint64_t)key >> 32 < (1u << (32 - NARROW_DATA_BITS)) &&
        ((uint64_t)key & 0xffffffffu) <= NARROW_DATA_MASK;
}

/* the index's keys in 8 bytes each from now on; -1 when out of memory */
static int index_widen(StateIndex *index)
{
    if (!index->narrow)
        return 0;
    Py_ssize_t capacity = index->count;
    int64_t *keys = PyMem_Realloc(index->keys, (capacity ? capacity : 1) * sizeof(int64_t));
    if (keys == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    index->keys = keys;
    index->key_capacity = capacity;
    for (Py_ssize_t id = index->count - 1; id >= 0; id--) {     /* (from the end: in place) */
        uint32_t narrow = ((const uint32_t *)keys)[id];
        keys[id] = ((int64_t)(narrow >> NARROW_DATA_BITS) << 32) | (narrow & NARROW_DATA_MASK);
    }
    index->narrow = 0;
    return 0;
}

/* the index's keys in 4 bytes each from now on where they all fit (``compact``); -1 */
static int index_narrow(StateIndex *index)
{
    if (index->narrow)
        return 0;
    for (Py_ssize_t id = 0; id < index->count; id++)
        if (!narrow_fits(index->keys[id]))
            return 0;
    uint32_t *narrow = (uint32_t *)index->keys;
    for (Py_ssize_t id = 0; id < index->count; id++) {     /* (from the start: in place) */
        int64_t key = index->keys[id];
        narrow[id] = (uint32_t)((uint64_t)key >> 32) << NARROW_DATA_BITS |
            (uint32_t)(key & NARROW_DATA_MASK);
    }
    index->key_capacity *= 2;           /* (the same bytes hold twice the keys) */
    index->narrow = 1;
    return 0;
}

static inline void index_set_key(StateIndex *index, Py_ssize_t id, int64_t key)
{
    if (index->narrow)
        ((uint32_t *)index->keys)[id] = (uint32_t)((uint64_t)key >> 32) << NARROW_DATA_BITS |
            (uint32_t)(key & NARROW_DATA_MASK);
    else
        index->keys[id] = key;
}

static int index_grow(StateIndex *index)
{
    uint64_t capacity = (index->mask + 1) * 2;
    int32_t *slots = new_slots(capacity);
    if (slots == NULL)
        return -1;
    for (Py_ssize_t id = 0; id < index->count; id++) {
        uint64_t position = mix64((uint64_t)index_key(index, id)) & (capacity - 1);
        while (slots[position] != EMPTY)
            position = (position + 1) & (capacity - 1);
        slots[position] = (int32_t)id;
    }
    PyMem_Free(index->slots);
    index->slots = slots;
    index->mask = capacity - 1;
    return 0;
}

/* an empty set of states */
static int index_init(StateIndex *index)
{
    memset(index, 0, sizeof(StateIndex));
    index->slots = new_slots(FIRST_CAPACITY);
    index->mask = FIRST_CAPACITY - 1;
    return index->slots != NULL ? 0 : -1;
}

static void index_free(StateIndex *index)
{
    PyMem_Free(index->keys);
    PyMem_Free(index->slots);
    memset(index, 0, sizeof(StateIndex));
}

/* the hash index of a set whose index was released, made again */
static int index_ensure(StateIndex *index)
{
    if (index->slots != NULL)
        return 0;
    uint64_t capacity = FIRST_CAPACITY;
    while ((uint64_t)index->count * 4 > capacity * 3)
        capacity *= 2;
    index->mask = capacity / 2 - 1;
    return index_grow(index);          /* (fills a new table twice that size) */
}

/* the id of ``key`` in ``index``, ``*is_new``; -1: new and not ``add``; -2 with an error */
static Py_ssize_t index_intern(StateIndex *index, int64_t key, int add, int *is_new)
{
    uint64_t position = mix64((uint64_t)key) & index->mask;
    for (;;) {
        int32_t id = index->slots[position];
        if (id == EMPTY)
            break;
        if (index_key(index, id) == key) {
            *is_new = 0;
            return id;
        }
        position = (position + 1) & index->mask;
    }
    *is_new = 1;
    if (!add)
        return -1;
    if (index->narrow && !narrow_fits(key) && index_widen(index) < 0)
        return -2;
    int64_t *keys = index->narrow ?
        reserve_gently(index->keys, &index->key_capacity, sizeof(uint32_t), index->count + 1) :
        reserve(index->keys, &index->key_capacity, sizeof(int64_t), index->count + 1);
    if (keys == NULL)
        return -2;
    index->keys = keys;
    Py_ssize_t id = index->count++;
    index_set_key(index, id, key);
    index->slots[position] = (int32_t)id;
    if ((uint64_t)index->count * 4 > (index->mask + 1) * 3 && index_grow(index) < 0)
        return -2;
    return id;
}

static inline int64_t state_key(int32_t frame, int32_t data)
{
    return ((int64_t)frame << 32) | (uint32_t)data;
}

/* the indexes (slots) of the states and their parts, made again when released */
static int ensure_index(PackedTable *self)
{
    if (vt_index(&self->frames) < 0 || vt_index(&self->data) < 0 ||
            vt_index(&self->signals) < 0)
        return -1;
    return index_ensure(&self->states);
}

/* the id of the state (frame id, data id) in the selected search's set, ``*is_new``; -1:
 * new and not ``add``; -2 with an error */
static inline Py_ssize_t intern_key(PackedTable *self, int32_t frame, int32_t data, int add,
                                    int *is_new)
{
    return index_intern(&self->states, state_key(frame, data), add, is_new);
}

/* The reduction's number of the state (frame id, data id) (``PartialOrder``'s C3), given
 * now when it has none and ``number``; -1: none; -2 with an error */
static Py_ssize_t place_of(PackedTable *self, int32_t frame, int32_t data, int number)
{
    if (self->places.slots == NULL && index_init(&self->places) < 0) {
        PyErr_NoMemory();
        return -2;
    }
    int is_new;
    Py_ssize_t place = index_intern(&self->places, state_key(frame, data), number, &is_new);
    if (place == -2)
        PyErr_NoMemory();
    return place;
}

/* ================================================================ spare data
 * A distributed worker steps states whose successors mostly belong to other workers; their
 * data segments, interned in ``data``, would stay there for good, so that every worker held
 * nearly every data segment of the whole search.  While ``sparing``, a step's new data
 * segment goes to ``spare`` instead (id SPARE | index), which the worker empties each round
 * (``clear_spare``) once it has sent those successors; the ones it keeps move to ``data``
 * when stored (``intern_keys``). */
#define SPARE 0x40000000

static int32_t data_intern(PackedTable *table, const uint32_t *items, Py_ssize_t length)
{
    if (!table->sparing)
        return vt_intern(&table->data, items, length);
    int32_t id = vt_find(&table->data, items, length);
    if (id >= 0)
        return id;
    if (table->data.count >= SPARE || table->spare.count >= SPARE) {
        PyErr_SetString(PyExc_OverflowError, "more than 2**30 distinct data segments");
        return -1;
    }
    id = vt_intern(&table->spare, items, length);
    return id < 0 ? -1 : (SPARE | id);
}

static inline const uint32_t *data_items(PackedTable *table, int32_t id, Py_ssize_t *length)
{
    return id & SPARE ? vt_read(&table->spare, id & ~SPARE, length) :
        vt_read(&table->data, id, length);
}

/* the data id ``id`` as ``data`` numbers it (a spare segment moved there); -1 */
static int32_t settled_data(PackedTable *table, int32_t id)
{
    if (!(id & SPARE))
        return id;
    Py_ssize_t length;
    const uint32_t *items = vt_read(&table->spare, id & ~SPARE, &length);
    return vt_intern(&table->data, items, length);
}

/* ============================================================== the step machine */

typedef struct {
    PackedTable *table;
    uint32_t *locals;           /* working copies */
    Py_ssize_t local_count;
    uint32_t *data;
    const uint32_t *io;         /* signal values (the context's) */
    int32_t pc;
    int data_changed, locals_changed;   /* whether the step wrote a different value */
    int lazy;                   /* inputs chosen where read (steps), or read from data */
    /* choices: the script to follow, the domain sizes met */
    int32_t script[MAX_CHOICES];
    Py_ssize_t script_length;
    int32_t sizes[MAX_CHOICES];
    Py_ssize_t size_count;
    /* the inputs chosen by the instruction running now: by signal index */
    uint32_t *chosen_epoch;
    int32_t *chosen_value;
    uint32_t epoch;
    Value temps[TEMPS];
    int tasks;                  /* a step of one task among several (waits may run) */
    int idle;                   /* the task waits: its step leaves the state as it is */
    int frame_op;               /* FRAME_ (``frame_step``): CALL's operands at ``call_at`` */
    Py_ssize_t call_at;
} Run;

static inline Value load(PackedTable *table, uint32_t id)
{
    Value v;
    v.tag = table->value_tag[id];
    v.d = table->value_number[id];
    v.id = (int32_t)id;
    return v;
}

static inline Value number(int tag, double d)
{
    Value v = {tag, d, -1};
    return v;
}

/* the id of a value computed here (-1 with an error) */
static inline int32_t store_id(PackedTable *table, Value v)
{
    if (v.id >= 0)
        return v.id;
    return number_id(table, v.tag, v.d, NULL);
}

static inline int numeric(Value v)
{
    return v.tag != T_OBJ;
}

static inline int integral(double d)
{
    return d == d && !isinf(d) && d == floor(d);
}

/* the signal values of a context */
static inline const uint32_t *context_signals(PackedTable *table, uint32_t context)
{
    Py_ssize_t length;
    return vt_items(&table->signals, table->context_io[context], &length);
}

/* read signal ``index`` as ``fused_step._read`` does */
static int read_signal(Run *run, int64_t index, Value *out)
{
    PackedTable *table = run->table;
    if (index < 0 || index >= table->io_length)
        return VM_UNSUPPORTED;          /* unbound signal data: Python raises */
    if (run->lazy && table->lazy_domain[index] != NULL) {
        if (run->chosen_epoch[index] == run->epoch) {
            *out = load(table, run->chosen_value[index]);
            return VM_DONE;
        }
        Py_ssize_t position = run->size_count;
        if (position >= MAX_CHOICES)
            return VM_UNSUPPORTED;
        run->sizes[run->size_count++] = table->lazy_size[index];
        int32_t chosen = position < run->script_length ? run->script[position] : 0;
        int32_t id = table->lazy_domain[index][chosen];
        run->chosen_epoch[index] = run->epoch;
        run->chosen_value[index] = id;
        *out = load(table, id);
        return VM_DONE;
    }
    *out = load(table, run->io[index]);
    return VM_DONE;
}

static int to_num(Value *v)
{
    double x = v->d;
    if (!(integral(x) && x >= -NUM_EXACT_INTEGER && x <= NUM_EXACT_INTEGER)) {
        if (x != x || isinf(x))
            return VM_ERROR;
        float rounded = (float)x;
        if (isinf(rounded))
            return VM_ERROR;            /* beyond the float32 range: ERR_NUM_LIMIT */
        x = (double)rounded;
    }
    *v = number(T_NUM, x + 0.0);        /* never -0.0, as values.to_num */
    return VM_DONE;
}

static int truth(Value v, int *out)
{
    if (v.tag == T_OBJ)
        return VM_UNSUPPORTED;
    *out = v.d != 0.0;
    return VM_DONE;
}

/* Python's ``x % 3.0`` */
static inline double modulo3(double x)
{
    double r = fmod(x, 3.0);
    return r < 0 ? r + 3.0 : r;
}

/* a syncident's (generation modulo 3, arrived), as library/tasks.py's ``_generation``
 * reads it (a value not a float: never written) */
static inline double sync_generation(Value v, int *arrived)
{
    *arrived = v.tag == T_NUM && v.d >= SYNC_ARRIVED;
    if (v.tag != T_NUM)
        return 0.0;
    return *arrived ? v.d - SYNC_ARRIVED : v.d;
}

/* set global data ``slot`` to ``v``: 0, -1 with an error */
static inline int set_data(Run *run, int32_t slot, Value v)
{
    int32_t id = store_id(run->table, v);
    if (id < 0)
        return -1;
    run->data_changed |= run->data[slot] != (uint32_t)id;
    run->data[slot] = (uint32_t)id;
    return 0;
}

static int integer_operands(Value a, Value b, long long *x, long long *y)
{
    if (!numeric(a) || !numeric(b) || a.tag == T_BOOL || b.tag == T_BOOL)
        return VM_UNSUPPORTED;
    if (!integral(a.d) || !integral(b.d) || b.d == 0.0)
        return VM_ERROR;               /* ERR_NOTINTVAL, ERR_DIVZERO */
    if (fabs(a.d) >= INT_LIMIT || fabs(b.d) >= INT_LIMIT)
        return VM_UNSUPPORTED;
    *x = (long long)a.d;
    *y = (long long)b.d;
    return VM_DONE;
}

#define MAX_PATH 16              /* component offsets of one element write */

/* Whether the cycle collector may leave ``object`` alone: an object it does not track (a
 * number, a string, a tuple it has found holds no such object) */
static inline int untracked(PyObject *object)
{
    return !PyObject_IS_GC(object) || !PyObject_GC_IsTracked(object);
}

/* A tuple the machine made out of untracked items, out of the collector's reach as the
 * collector itself would put it at its next pass (``_PyTuple_MaybeUntrack``): the arrays
 * of 512 records a step writes would otherwise each be walked by the next collections. */
static inline void untrack_tuple(PyObject *tuple)
{
    for (Py_ssize_t i = 0; i < PyTuple_GET_SIZE(tuple); i++)
        if (!untracked(PyTuple_GET_ITEM(tuple, i)))
            return;
    PyObject_GC_UnTrack(tuple);
}

/* ``value`` with its part at ``path`` (``depth`` offsets) replaced by ``item``, the tuples
 * along the path rebuilt (``machine.replace_at``): a new reference; NULL with an error
 * set, or NULL without one where a part on the path is not a tuple that long */
static PyObject *replaced_at(PyObject *value, const int32_t *path, int32_t depth,
                             PyObject *item)
{
    if (depth == 0) {
        Py_INCREF(item);
        return item;
    }
    if (!PyTuple_Check(value) || path[0] < 0 || path[0] >= PyTuple_GET_SIZE(value))
        return NULL;
    PyObject *inner = replaced_at(PyTuple_GET_ITEM(value, path[0]), path + 1, depth - 1, item);
    if (inner == NULL)
        return NULL;
    Py_ssize_t length = PyTuple_GET_SIZE(value);
    PyObject *changed = PyTuple_New(length);
    if (changed == NULL) {
        Py_DECREF(inner);
        return NULL;
    }
    for (Py_ssize_t i = 0; i < length; i++) {
        PyObject *kept = i == path[0] ? inner : PyTuple_GET_ITEM(value, i);
        if (i != path[0])
            Py_INCREF(kept);
        PyTuple_SET_ITEM(changed, i, kept);
    }
    /* (the other items are those of ``value``: untracked where it is) */
    if (untracked(value) && untracked(inner))
        PyObject_GC_UnTrack(changed);
    return changed;
}

/* Run ``code`` from ``ip`` until the block sets the pc (VM_DONE), an error (VM_ERROR) or
 * what Python must do (VM_UNSUPPORTED).  Atom code (``bits``) runs to OP_END. */
static int execute(Run *run, const int32_t *code, Py_ssize_t ip, uint64_t *bits)
{
    PackedTable *table = run->table;
    Value stack[STACK_SIZE];
    int top = 0;                /* items on the stack */
    Py_ssize_t atom_end = -1;   /* atoms: where the next atom starts */
    int outcome;
#define POP() (stack[--top])
#define PUSH(v) (stack[top++] = (v))
#define FAIL(o) do { outcome = (o); goto failed; } while (0)
    for (;;) {
        int32_t op = code[ip++];
        switch (op) {
        case OP_CONST:
            PUSH(load(table, (uint32_t)code[ip++]));
            break;
        case OP_LOAD_STORE:
            PUSH(load(table, run->data[code[ip++]]));
            break;
        case OP_LOAD_LOCAL: {
            int32_t slot = code[ip++];
            if (slot >= run->local_count)
                FAIL(VM_UNSUPPORTED);
            PUSH(load(table, run->locals[slot]));
            break;
        }
        case OP_READ: {
            Value v;
            if ((outcome = read_signal(run, code[ip++], &v)) != VM_DONE)
                goto failed;
            PUSH(v);
            break;
        }
        case OP_READ_DYN: {
            Value index = POP(), v;
            if (index.tag != T_INT)
                FAIL(VM_UNSUPPORTED);
            if ((outcome = read_signal(run, (int64_t)index.d, &v)) != VM_DONE)
                goto failed;
            PUSH(v);
            break;
        }
        case OP_ADD: case OP_SUB: case OP_MUL: {
            Value b = POP(), a = POP();
            if (!numeric(a) || !numeric(b))
                FAIL(VM_UNSUPPORTED);
            double r = op == OP_ADD ? a.d + b.d : op == OP_SUB ? a.d - b.d : a.d * b.d;
            /* Python: int op int stays an int (then rounded by _to_num), else a float */
            int tag = a.tag != T_NUM && b.tag != T_NUM ? T_INT : T_NUM;
            if (tag == T_INT && fabs(r) >= 9007199254740992.0)
                FAIL(VM_UNSUPPORTED);
            PUSH(number(tag, r));
            break;
        }
        case OP_DIVIDE: {
            Value b = POP(), a = POP();
            if (!numeric(a) || !numeric(b))
                FAIL(VM_UNSUPPORTED);
            if (b.d == 0.0)
                FAIL(VM_ERROR);                 /* ERR_DIVZERO */
            PUSH(number(T_NUM, a.d / b.d));
            break;
        }
        case OP_TO_NUM: {
            Value v = POP();
            if (!numeric(v))
                FAIL(VM_UNSUPPORTED);
            if ((outcome = to_num(&v)) != VM_DONE)
                goto failed;
            PUSH(v);
            break;
        }
        case OP_TO_DNUM: {
            Value v = POP();
            if (!numeric(v))
                FAIL(VM_UNSUPPORTED);
            if (v.d != v.d || isinf(v.d))
                FAIL(VM_ERROR);
            PUSH(number(T_NUM, v.d));
            break;
        }
        case OP_INT_DIV: case OP_INT_MOD: {
            Value b = POP(), a = POP();
            long long x, y;
            if ((outcome = integer_operands(a, b, &x, &y)) != VM_DONE)
                goto failed;
            long long ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, r;
            if (op == OP_INT_DIV)
                r = (x < 0) == (y < 0) ? ax / ay : -(ax / ay);
            else
                r = x >= 0 ? ax % ay : -(ax % ay);
            PUSH(number(T_NUM, (double)r));
            break;
        }
        case OP_NEG: {
            Value v = POP();
            if (!numeric(v))
                FAIL(VM_UNSUPPORTED);
            /* + 0.0: negation never makes -0.0, as in the Python step */
            PUSH(number(v.tag == T_NUM ? T_NUM : T_INT, -v.d + 0.0));
            break;
        }
        case OP_NOT: {
            int t;
            if ((outcome = truth(POP(), &t)) != VM_DONE)
                goto failed;
            PUSH(number(T_BOOL, !t));
            break;
        }
        case OP_EQ: case OP_NE: {
            Value b = POP(), a = POP();
            int equal;
            if (numeric(a) && numeric(b))
                equal = a.d == b.d;
            else if (a.tag == T_OBJ && b.tag == T_OBJ)
                equal = a.id == b.id;
            else
                FAIL(VM_UNSUPPORTED);
            PUSH(number(T_BOOL, op == OP_EQ ? equal : !equal));
            break;
        }
        case OP_LT: case OP_LE: case OP_GT: case OP_GE: {
            Value b = POP(), a = POP();
            if (!numeric(a) || !numeric(b))
                FAIL(VM_UNSUPPORTED);
            int r = op == OP_LT ? a.d < b.d : op == OP_LE ? a.d <= b.d :
                op == OP_GT ? a.d > b.d : a.d >= b.d;
            PUSH(number(T_BOOL, r));
            break;
        }
        case OP_AND: case OP_OR: {
            Value b = POP(), a = POP();
            if (a.tag == T_OBJ || b.tag == T_OBJ || a.tag == T_NUM || b.tag == T_NUM)
                FAIL(VM_UNSUPPORTED);
            long long x = (long long)a.d, y = (long long)b.d;
            PUSH(number(T_BOOL, op == OP_AND ? (x & y) != 0 : (x | y) != 0));
            break;
        }
        case OP_SET_STORE: {
            int32_t id = store_id(table, POP());
            if (id < 0)
                return -1;
            int32_t slot = code[ip++];
            run->data_changed |= run->data[slot] != (uint32_t)id;
            run->data[slot] = (uint32_t)id;
            break;
        }
        case OP_SET_LOCAL: {
            int32_t slot = code[ip++];
            if (slot >= run->local_count)
                FAIL(VM_UNSUPPORTED);
            int32_t id = store_id(table, POP());
            if (id < 0)
                return -1;
            run->locals_changed |= run->locals[slot] != (uint32_t)id;
            run->locals[slot] = (uint32_t)id;
            break;
        }
        case OP_SET_TEMP:
            run->temps[code[ip++]] = POP();
            break;
        case OP_GET_TEMP:
            PUSH(run->temps[code[ip++]]);
            break;
        case OP_GOTO:
            run->pc = code[ip];
            return VM_DONE;
        case OP_BRANCH: {
            int t;
            if ((outcome = truth(POP(), &t)) != VM_DONE)
                goto failed;
            run->pc = t ? code[ip] : code[ip + 1];
            return VM_DONE;
        }
        case OP_GOTO_IF: {
            int t;
            if ((outcome = truth(POP(), &t)) != VM_DONE)
                goto failed;
            if (t) {
                run->pc = code[ip];
                return VM_DONE;
            }
            ip++;
            break;
        }
        case OP_RESET_CHOSEN:
            run->epoch++;
            break;
        case OP_UNSUPPORTED:
            FAIL(VM_UNSUPPORTED);
        case OP_FOR_DEFAULT_STEP: {     /* temps 0, 1: first, last */
            Value first = run->temps[0], last = run->temps[1];
            if (!numeric(first) || !numeric(last))
                FAIL(VM_UNSUPPORTED);
            PUSH(number(T_NUM, first.d > last.d ? -1.0 : 1.0));
            break;
        }
        case OP_FOR_INIT: {             /* temps 0, 1, 2: first, last, step */
            int32_t slot = code[ip];
            Value first = run->temps[0], last = run->temps[1];
            if (slot + 2 >= run->local_count || !numeric(first) || !numeric(last))
                FAIL(VM_UNSUPPORTED);
            for (int i = 0; i < 3; i++) {
                int32_t id = store_id(table, run->temps[i]);
                if (id < 0)
                    return -1;
                run->locals_changed |= run->locals[slot + i] != (uint32_t)id;
                run->locals[slot + i] = (uint32_t)id;
            }
            double low = first.d <= last.d ? first.d : last.d;
            double high = first.d <= last.d ? last.d : first.d;
            run->pc = low <= first.d && first.d <= high ? code[ip + 1] : code[ip + 2];
            return VM_DONE;
        }
        case OP_FOR_NEXT: {
            int32_t slot = code[ip];
            if (slot + 2 >= run->local_count)
                FAIL(VM_UNSUPPORTED);
            Value value = load(table, run->locals[slot]);
            Value last = load(table, run->locals[slot + 1]);
            Value step = load(table, run->locals[slot + 2]);
            if (!numeric(value) || !numeric(last) || !numeric(step))
                FAIL(VM_UNSUPPORTED);
            Value sum = number(value.tag != T_NUM && step.tag != T_NUM ? T_INT : T_NUM,
                               value.d + step.d);
            if ((outcome = to_num(&sum)) != VM_DONE)
                goto failed;
            int32_t id = store_id(table, sum);
            if (id < 0)
                return -1;
            run->locals_changed |= run->locals[slot] != (uint32_t)id;
            run->locals[slot] = (uint32_t)id;
            int go_on = step.d >= 0 ? sum.d <= last.d : sum.d >= last.d;
            run->pc = go_on ? code[ip + 1] : code[ip + 2];
            return VM_DONE;
        }
        case OP_ATOM_BEGIN:
            atom_end = code[ip++];
            top = 0;
            break;
        case OP_ATOM_END: {
            int32_t bit = code[ip++];
            int t;
            if ((outcome = truth(POP(), &t)) != VM_DONE)
                goto failed;
            if (t)
                *bits |= (uint64_t)1 << bit;
            break;
        }
        case OP_END:
            return VM_DONE;
        case OP_TASK_ONLY:          /* waits: only as one task's step among several */
            if (!run->tasks)
                FAIL(VM_UNSUPPORTED);
            break;
        case OP_JUMP_IF_FALSE: {
            int t;
            int32_t skip = code[ip++];
            if ((outcome = truth(POP(), &t)) != VM_DONE)
                goto failed;
            if (!t)
                ip += skip;
            break;
        }
        case OP_REQUIRE: {          /* what the code was compiled for, else Python */
            int t;
            if ((outcome = truth(POP(), &t)) != VM_DONE)
                goto failed;
            if (!t)
                FAIL(VM_UNSUPPORTED);
            break;
        }
        case OP_POP:
            top--;
            break;
        case OP_CHOOSE_BOOL: {      /* ``m.choose(name, (False, True))`` */
            Py_ssize_t position = run->size_count;
            if (position >= MAX_CHOICES)
                FAIL(VM_UNSUPPORTED);
            run->sizes[run->size_count++] = 2;
            PUSH(number(T_BOOL, position < run->script_length && run->script[position]));
            break;
        }
        case OP_CHOOSE_CONST: {     /* ``m.choose(name, domain)``: count, the values' ids */
            Py_ssize_t position = run->size_count;
            int32_t count = code[ip];
            if (position >= MAX_CHOICES || count <= 0)
                FAIL(VM_UNSUPPORTED);
            run->sizes[run->size_count++] = count;
            int32_t chosen = position < run->script_length ? run->script[position] : 0;
            PUSH(load(table, (uint32_t)code[ip + 1 + chosen]));
            ip += 1 + count;
            break;
        }
        case OP_CHECK_INDEX: {      /* an index of the array in global data ``slot`` */
            Value index = POP();
            PyObject *array = table->value_object[run->data[code[ip++]]];
            if (!numeric(index) || index.tag == T_BOOL || array == NULL ||
                    !PyTuple_Check(array))
                FAIL(VM_UNSUPPORTED);
            if (!integral(index.d) || index.d < 1.0 ||
                    index.d > (double)PyTuple_GET_SIZE(array))
                FAIL(VM_ERROR);             /* ERR_OUTOFBND: Python raises */
            break;
        }
        case OP_SET_ELEMENT: {      /* element (index, value) of the array in ``slot``, or
                                     * the component at the path's offsets of that element */
            Value value = POP(), index = POP();
            int32_t slot = code[ip], depth = code[ip + 1];
            const int32_t *offsets = code + ip + 2;
            ip += 2 + depth;
            PyObject *array = table->value_object[run->data[slot]];
            if (!numeric(index) || index.tag == T_BOOL || array == NULL ||
                    !PyTuple_Check(array) || depth < 0 || depth >= MAX_PATH)
                FAIL(VM_UNSUPPORTED);
            if (!integral(index.d) || index.d < 1.0 ||
                    index.d > (double)PyTuple_GET_SIZE(array))
                FAIL(VM_ERROR);             /* ERR_OUTOFBND: Python raises */
            int32_t element = (int32_t)index.d - 1;
            int32_t value_id_ = store_id(table, value);
            if (value_id_ < 0)
                return -1;
            PyObject *item = value_object(table, value_id_);
            if (item == NULL)
                return -1;
            /* the element written: the value, or the element with its component replaced */
            PyObject *written = replaced_at(PyTuple_GET_ITEM(array, element), offsets, depth,
                                            item);
            Py_DECREF(item);
            if (written == NULL) {
                if (PyErr_Occurred())
                    return -1;
                FAIL(VM_UNSUPPORTED);       /* (not a record of that shape: Python's) */
            }
            int32_t id;
            if (PyTuple_GET_SIZE(array) >= BIG_TUPLE &&
                    run->data[slot] < (uint32_t)table->big_sums_capacity)
                id = big_replaced_id(table, (int32_t)run->data[slot], array, element, written);
            else {
                PyObject *changed = replaced_at(array, &element, 1, written);
                id = changed == NULL ? -1 : value_id(table, changed);
                Py_XDECREF(changed);
            }
            Py_DECREF(written);
            if (id < 0)
                return -1;
            run->data_changed |= run->data[slot] != (uint32_t)id;
            run->data[slot] = (uint32_t)id;
            break;
        }
        case OP_BUILD_TUPLE: {      /* an aggregate of the top ``count`` values */
            int32_t count = code[ip++];
            if (count <= 0 || count > top)
                FAIL(VM_UNSUPPORTED);
            PyObject *tuple = PyTuple_New(count);
            if (tuple == NULL)
                return -1;
            top -= count;
            for (int32_t i = 0; i < count; i++) {
                int32_t item_id = store_id(table, stack[top + i]);
                PyObject *item = item_id < 0 ? NULL : value_object(table, item_id);
                if (item == NULL) {
                    Py_DECREF(tuple);
                    return -1;
                }
                PyTuple_SET_ITEM(tuple, i, item);
            }
            untrack_tuple(tuple);
            int32_t id = value_id(table, tuple);
            Py_DECREF(tuple);
            if (id < 0)
                return -1;
            PUSH(load(table, (uint32_t)id));
            break;
        }
        case OP_CALL: {             /* callee, its locals' count and initial ids, the
                                     * arguments' count and (slot, num) of each */
            int32_t locals = code[ip + 1], count = code[ip + 2 + locals];
            const int32_t *params = code + ip + 3 + locals;
            if (count < 0 || count > TEMPS || count > top)
                FAIL(VM_UNSUPPORTED);
            for (int32_t k = count - 1; k >= 0; k--) {
                Value v = POP();
                /* (``Parameter.convert``: a num argument rounded to single precision) */
                if (params[2 * k + 1] && v.tag == T_NUM &&
                        (outcome = to_num(&v)) != VM_DONE)
                    goto failed;
                run->temps[k] = v;
            }
            run->frame_op = FRAME_CALL;
            run->call_at = ip;
            return VM_DONE;
        }
        case OP_LEAVE:
            run->frame_op = FRAME_LEAVE;
            return VM_DONE;
        case OP_WAIT:               /* the task waits: the pc stays */
            run->idle = 1;
            return VM_DONE;
        case OP_SYNC: {             /* own slot, unshared, next pc, partners, their slots */
            int32_t own = code[ip], unshared = code[ip + 1], next = code[ip + 2];
            int32_t count = code[ip + 3];
            const int32_t *partners = code + ip + 4;
            int arrived, other;
            double current = sync_generation(load(table, run->data[own]), &arrived);
            double generation = arrived ? current : modulo3(current + 1.0);
            if (unshared && count == 0 && !arrived) {
                run->pc = next;             /* no loaded task shares it: no count kept */
                return VM_DONE;
            }
            double ahead = modulo3(generation + 1.0);
            int missing = 0;
            for (int32_t i = 0; i < count && !missing; i++) {
                double theirs = partners[i] < 0 ? -1.0 :
                    sync_generation(load(table, run->data[partners[i]]), &other);
                missing = theirs != generation && theirs != ahead;
            }
            if (!missing) {
                if (set_data(run, own, number(T_NUM, generation)) < 0)
                    return -1;
                run->pc = next;
                return VM_DONE;
            }
            if (arrived) {
                run->idle = 1;              /* still waiting */
                return VM_DONE;
            }
            if (set_data(run, own, number(T_NUM, generation + SYNC_ARRIVED)) < 0)
                return -1;
            return VM_DONE;                 /* arrived: the pc stays */
        }
        default:
            PyErr_Format(PyExc_SystemError, "step machine: bad opcode %d", (int)op);
            return -1;
        }
        if (top >= STACK_SIZE - 2) {
            PyErr_SetString(PyExc_SystemError, "step machine: stack overflow");
            return -1;
        }
        continue;
    failed:
        if (outcome == VM_ERROR && atom_end >= 0) {
            ip = atom_end;          /* an atom whose evaluation raises is false */
            top = 0;
            continue;
        }
        return outcome;
    }
#undef POP
#undef PUSH
#undef FAIL
}

/* the choices after the script (``choosers.next_script``): 0 when every one is done */
static int next_script(Run *run)
{
    for (Py_ssize_t i = run->size_count - 1; i >= 0; i--) {
        int32_t current = i < run->script_length ? run->script[i] : 0;
        if (current + 1 < run->sizes[i]) {
            for (Py_ssize_t j = run->script_length; j < i; j++)
                run->script[j] = 0;
            run->script[i] = current + 1;
            run->script_length = i + 1;
            return 1;
        }
    }
    return 0;
}

typedef struct {            /* the successors one state's step gave */
    int32_t *frames, *data;
    Py_ssize_t count, capacity;
} Successors;

static int add_successor(Successors *found, int32_t frame, int32_t data)
{
    Py_ssize_t capacity = found->capacity;
    int32_t *frames = reserve(found->frames, &capacity, sizeof(int32_t), found->count + 1);
    if (frames == NULL)
        return -1;
    found->frames = frames;
    capacity = found->capacity;
    int32_t *datas = reserve(found->data, &capacity, sizeof(int32_t), found->count + 1);
    if (datas == NULL)
        return -1;
    found->data = datas;
    found->capacity = capacity;
    found->frames[found->count] = frame;
    found->data[found->count++] = data;
    return 0;
}

typedef struct Scratch {     /* scratch space of the step machine */
    uint32_t *frame, *data;     /* the vectors a run works on */
    Py_ssize_t frame_capacity, data_capacity;
    uint32_t *source;           /* the stepped state's vectors, copied out of the tables
                                 * (whose arenas move when a successor is interned) */
    Py_ssize_t source_capacity;
    Int32Vector ran;            /* (routine, pc) pairs whose blocks ran in this state's step,
                                 * not yet known */
    Successors found;           /* (for ``successor_ids``) */
    Int32Vector changed, owners;    /* several tasks: per successor, whether it changes the
                                     * state, the task that took the step (+ TASK_COUNT_MAX
                                     * when Python took it) */
    Int32Vector waited;         /* the machine's idle steps: (successor, routine, pc) each,
                                 * whose pc is noted as run only if the step is kept */
    uint32_t *chosen_epoch;
    int32_t *chosen_value;
    uint32_t epoch;
    /* the reduced step (``ample_step``): the (routine, pc, task) triples its runs
     * noted, told once the ample set is known (``defer``); no notes (``silent``) while it
     * probes whether a task goes on; a successor's vectors copied out while it runs on */
    int defer, silent;
    int32_t defer_task;
    int numbered;               /* ``tasks_step`` numbered the state it steps */
    Int32Vector pending;
    uint32_t *probe_source;
    Py_ssize_t probe_capacity;
    Successors probe;
    Int32Vector probe_changed;
    uint32_t *called;           /* the frame vector a call or a return makes */
    Py_ssize_t called_capacity;
    uint32_t *question;         /* a question of ``entered_context``, then its answer */
    Py_ssize_t question_capacity;
} Scratch;

static int scratch_init(Scratch *scratch, PackedTable *table)
{
    Py_ssize_t io = table->io_length ? table->io_length : 1;
    scratch->chosen_epoch = PyMem_Calloc(io, sizeof(uint32_t));
    scratch->chosen_value = PyMem_Calloc(io, sizeof(int32_t));
    scratch->epoch = 1;
    if (scratch->chosen_epoch == NULL || scratch->chosen_value == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    return 0;
}

static void scratch_free(Scratch *scratch)
{
    PyMem_Free(scratch->frame);
    PyMem_Free(scratch->data);
    PyMem_Free(scratch->source);
    PyMem_Free(scratch->chosen_epoch);
    PyMem_Free(scratch->chosen_value);
    vector32_free(&scratch->ran);
    vector32_free(&scratch->changed);
    vector32_free(&scratch->owners);
    vector32_free(&scratch->waited);
    vector32_free(&scratch->pending);
    vector32_free(&scratch->probe_changed);
    PyMem_Free(scratch->probe_source);
    PyMem_Free(scratch->called);
    PyMem_Free(scratch->question);
    PyMem_Free(scratch->probe.frames);
    PyMem_Free(scratch->probe.data);
    PyMem_Free(scratch->found.frames);
    PyMem_Free(scratch->found.data);
}

/* set ``items[slot] = id`` for the (slot, id) pairs; whether one changed */
static inline int reset(uint32_t *items, Py_ssize_t length, const int32_t *pairs,
                        int32_t from, int32_t to)
{
    int changed = 0;
    for (int32_t i = from; i < to; i++) {
        int32_t slot = pairs[2 * i];
        uint32_t id = (uint32_t)pairs[2 * i + 1];
        if (slot < length && items[slot] != id) {
            items[slot] = id;
            changed = 1;
        }
    }
    return changed;
}

/* The model's projection of a step's target (model/reduction/projection.py): sliced and
 * dead data at their initial values, by the routine's and main's pc. */
static void project(PackedTable *table, Routine *routine, uint32_t context, Run *run)
{
    if (routine->reset_offsets != NULL)
        run->locals_changed |= reset(run->locals, run->local_count, routine->reset_pairs,
                                     routine->reset_offsets[run->pc],
                                     routine->reset_offsets[run->pc + 1]);
    Resets *resets = &table->global_resets;
    int32_t list = 0;
    if ((table->context_runs[context] & CONTEXT_MAIN_ALONE) && table->main_resets.lists > 0) {
        resets = &table->main_resets;
        list = run->pc;
    }
    if (resets->offsets != NULL && list < resets->lists)
        run->data_changed |= reset(run->data, table->store_length, resets->pairs,
                                   resets->offsets[list], resets->offsets[list + 1]);
}

/* the frame ``frame`` (id ``frame_id``) with the program counter ``pc`` (remembered in a
 * small cache by (frame id, pc)); -1 with an error */
static int32_t frame_at(PackedTable *table, int32_t frame_id, const uint32_t *frame,
                        Py_ssize_t length, int32_t pc, uint32_t *work)
{
    uint64_t key = (uint64_t)(uint32_t)frame_id << 32 | (uint32_t)pc;
    uint64_t slot = mix64(key) & (FRAME_CACHE - 1);
    if (table->frame_cache_key[slot] == key + 1)
        return table->frame_cache_value[slot];
    memcpy(work, frame, length * sizeof(uint32_t));
    work[1] = (uint32_t)pc;
    int32_t id = vt_intern(&table->frames, work, length);
    if (id >= 0) {
        table->frame_cache_key[slot] = key + 1;
        table->frame_cache_value[slot] = id;
    }
    return id;
}

typedef struct {            /* a stored state's segments, as the tables hold them now */
    int32_t frame_id, data_id;
    const uint32_t *frame, *data;
    Py_ssize_t frame_length, data_length;
} Stored;

static void stored_state(PackedTable *table, Py_ssize_t id, Stored *stored)
{
    int64_t key = index_key(&table->states, id);
    stored->frame_id = (int32_t)(key >> 32);
    stored->data_id = (int32_t)(key & 0xffffffff);
    stored->frame = vt_items(&table->frames, stored->frame_id, &stored->frame_length);
    stored->data = data_items(table, stored->data_id, &stored->data_length);
}

/* The stepped state's vectors copied out of the tables (interning a successor may move
 * their arenas) into ``scratch->source``: ``*frame`` and ``*data`` point there; -1 */
static int copy_source(Scratch *scratch, const uint32_t *stored_frame, Py_ssize_t frame_length,
                       const uint32_t *stored_data, Py_ssize_t data_length,
                       const uint32_t **frame, const uint32_t **data)
{
    uint32_t *source = reserve(scratch->source, &scratch->source_capacity, sizeof(uint32_t),
                               frame_length + data_length + 1);
    if (source == NULL)
        return -1;
    scratch->source = source;
    memcpy(source, stored_frame, frame_length * sizeof(uint32_t));
    memcpy(source + frame_length, stored_data, data_length * sizeof(uint32_t));
    *frame = source;
    *data = source + frame_length;
    return 0;
}

/* A run over working copies of the vectors (``run->locals`` still to be set): -1 */
static int start_run(Run *run, PackedTable *table, Scratch *scratch, Py_ssize_t frame_length,
                     Py_ssize_t data_length, uint32_t context)
{
    uint32_t *work_frame = reserve(scratch->frame, &scratch->frame_capacity, sizeof(uint32_t),
                                   frame_length);
    if (work_frame == NULL)
        return -1;
    scratch->frame = work_frame;
    uint32_t *work_data = reserve(scratch->data, &scratch->data_capacity, sizeof(uint32_t),
                                  data_length + 1);
    if (work_data == NULL)
        return -1;
    scratch->data = work_data;
    run->table = table;
    run->data = work_data;
    run->io = context_signals(table, context);
    run->lazy = 1;
    run->script_length = 0;
    run->chosen_epoch = scratch->chosen_epoch;
    run->chosen_value = scratch->chosen_value;
    run->tasks = run->idle = 0;
    return 0;
}

/* The successors of state ``id`` by the step machine, as ``fused_successor_states``
 * gives them: VM_DONE (``found`` filled), VM_UNSUPPORTED (Python must step it: nothing
 * changed), -1 with an error. */
static int machine_step(PackedTable *table, Py_ssize_t id, Scratch *scratch,
                        Successors *found);
static int tasks_step(PackedTable *table, Py_ssize_t id, Scratch *scratch, Successors *found);

/* note (routine, pc) as run by a step in progress (known once the step is done) */
static inline int note_ran(PackedTable *table, Scratch *scratch, int32_t routine, int32_t pc)
{
    if (scratch->silent)
        return 0;
    if (scratch->defer)
        return vector32_push(&scratch->pending, routine) < 0 ||
            vector32_push(&scratch->pending, pc) < 0 ||
            vector32_push(&scratch->pending, scratch->defer_task) < 0 ? -1 : 0;
    uint8_t *executed = &table->routines[routine].executed[pc];
    if (*executed)
        return 0;
    *executed = 2;
    if (vector32_push(&scratch->ran, routine) < 0 || vector32_push(&scratch->ran, pc) < 0)
        return -1;
    return 0;
}

/* forget the pcs noted from pair ``from`` on (a step given up: Python says what runs) */
static void forget_ran(PackedTable *table, Scratch *scratch, Py_ssize_t from)
{
    for (Py_ssize_t i = from; i + 1 < scratch->ran.length; i += 2)
        table->routines[scratch->ran.items[i]].executed[scratch->ran.items[i + 1]] = 0;
    scratch->ran.length = from;
}

/* ``machine_step`` (or ``tasks_step`` with several tasks), with the pcs its blocks ran
 * noted as executed when it is done (and forgotten when it gave up: the Python step then
 * says what runs) */
static int machine_successors(PackedTable *table, Py_ssize_t id, Scratch *scratch,
                              Successors *found)
{
    scratch->ran.length = 0;
    int outcome = table->task_count > 1 ? tasks_step(table, id, scratch, found) :
        machine_step(table, id, scratch, found);
    if (outcome != VM_DONE) {
        forget_ran(table, scratch, 0);
        return outcome;
    }
    for (Py_ssize_t i = 0; i < scratch->ran.length; i++) {
        if (i % 2)
            table->routines[scratch->ran.items[i - 1]].executed[scratch->ran.items[i]] = 1;
        if (vector32_push(&table->newly_executed, scratch->ran.items[i]) < 0)
            return -1;
    }
    scratch->ran.length = 0;
    return outcome;
}

static int machine_step(PackedTable *table, Py_ssize_t id, Scratch *scratch,
                        Successors *found)
{
    Stored stored;
    stored_state(table, id, &stored);
    int32_t frame_id = stored.frame_id, data_id = stored.data_id;
    Py_ssize_t frame_length = stored.frame_length, data_length = stored.data_length;
    const uint32_t *stored_frame = stored.frame, *stored_data = stored.data;
    uint32_t context = stored_frame[0];
    if (frame_length < 2 || !(table->context_runs[context] & CONTEXT_RUNS))
        return VM_UNSUPPORTED;
    int32_t routine_index = table->context_routine[context];
    if (routine_index < 0 || routine_index >= table->routine_count)
        return VM_UNSUPPORTED;
    Routine *routine = &table->routines[routine_index];
    int32_t start_pc = (int32_t)stored_frame[1];
    if (routine->code == NULL || start_pc < 0 || start_pc >= routine->length ||
            routine->block_start[start_pc] < 0)
        return VM_UNSUPPORTED;
    const uint32_t *frame, *data;
    Run run;
    if (copy_source(scratch, stored_frame, frame_length, stored_data, data_length,
                    &frame, &data) < 0 ||
            start_run(&run, table, scratch, frame_length, data_length, context) < 0)
        return -1;
    uint32_t *work_frame = scratch->frame, *work_data = scratch->data;
    run.locals = work_frame + 2;
    run.local_count = frame_length - 2;
    found->count = 0;
    run.data_changed = run.locals_changed = 1;
    for (;;) {
        if (run.locals_changed)                 /* (the last run's copies, if unchanged) */
            memcpy(work_frame, frame, frame_length * sizeof(uint32_t));
        if (run.data_changed)
            memcpy(work_data, data, data_length * sizeof(uint32_t));
        run.data_changed = run.locals_changed = 0;
        run.pc = start_pc;
        run.size_count = 0;
        run.epoch = ++scratch->epoch;
        int seen_visible = routine->first_visible[start_pc];
        int blocks = 0;
        for (;;) {
            int32_t at = routine->block_start[run.pc];
            if (at < 0 || ++blocks > MAX_BLOCKS_PER_STEP)
                return VM_UNSUPPORTED;
            if (note_ran(table, scratch, routine_index, run.pc) < 0)
                return -1;
            int outcome = execute(&run, routine->code, at, NULL);
            scratch->epoch = run.epoch;
            if (outcome != VM_DONE)
                return outcome < 0 ? -1 : VM_UNSUPPORTED;
            if (run.pc < 0 || run.pc >= routine->length)
                return VM_UNSUPPORTED;
            int kind = routine->kinds[run.pc];
            if (kind & 2)
                break;
            if (kind & 1) {
                if (seen_visible)
                    break;
                seen_visible = 1;
            }
            if ((kind & 4) && run.size_count)
                break;
        }
        if (table->projecting)
            project(table, routine, context, &run);
        int32_t new_frame;
        if (run.locals_changed) {
            work_frame[1] = (uint32_t)run.pc;
            new_frame = vt_intern(&table->frames, work_frame, frame_length);
        }
        else            /* the same context and locals at another pc: often seen before */
            new_frame = frame_at(table, frame_id, frame, frame_length, run.pc, work_frame);
        int32_t new_data = new_frame < 0 ? -1 : !run.data_changed ? data_id :
            data_intern(table, work_data, data_length);
        if (new_data < 0 || add_successor(found, new_frame, new_data) < 0)
            return -1;
        if (run.size_count == 0 || !next_script(&run))
            return VM_DONE;
    }
}

/* The TASK_INFO numbers of ``task`` in the context of frame segment ``frame_id`` (its
 * first item), which goes to ``*context`` */
static const int32_t *task_info_at(PackedTable *table, int32_t frame_id, Py_ssize_t task,
                                   uint32_t *context)
{
    Py_ssize_t length;
    *context = vt_items(&table->frames, frame_id, &length)[0];
    return table->context_tasks + ((Py_ssize_t)*context * table->task_count + task) * TASK_INFO;
}

/* The answer (an id of ``frame_answers``: entered context, pc, the caller's locals) to a
 * step that changes ``task``'s frames in ``context``: its call (``op`` FRAME_CALL, at
 * ``pc``, of routine ``callee``, the caller's ``locals`` value ids at ``caller``) or its
 * return (FRAME_LEAVE).  Python answers each question once (``called_context``,
 * ``left_context``: a function of the context and the caller's locals); the answer is
 * kept.  NO_ANSWER where Python steps it, -2 with an error. */
static int32_t entered_context(PackedTable *table, Scratch *scratch, int op, uint32_t context,
                               Py_ssize_t task, int32_t pc, int32_t callee,
                               const uint32_t *caller, int32_t locals)
{
    Py_ssize_t length = op == FRAME_CALL ? 5 + locals : 3;
    uint32_t *question = reserve(scratch->question, &scratch->question_capacity,
                                 sizeof(uint32_t), length);
    if (question == NULL)
        return -2;
    scratch->question = question;
    question[0] = (uint32_t)op;
    question[1] = context;
    question[2] = (uint32_t)task;
    if (op == FRAME_CALL) {
        question[3] = (uint32_t)pc;
        question[4] = (uint32_t)callee;
        memcpy(question + 5, caller, locals * sizeof(uint32_t));
    }
    if (vt_index(&table->frame_questions) < 0 || vt_index(&table->frame_answers) < 0)
        return -2;
    int32_t asked = vt_intern(&table->frame_questions, question, length);
    if (asked < 0)
        return -2;
    if (asked < table->answer_of.length)
        return table->answer_of.items[asked];
    PyObject *answer = op == FRAME_CALL ?
        PyObject_CallMethod((PyObject *)table, "called_context", "nnnny#", (Py_ssize_t)context,
                            task, (Py_ssize_t)pc, (Py_ssize_t)callee, (const char *)caller,
                            (Py_ssize_t)(locals * sizeof(uint32_t))) :
        PyObject_CallMethod((PyObject *)table, "left_context", "nn", (Py_ssize_t)context, task);
    if (answer == NULL)
        return -2;
    int32_t answer_id = NO_ANSWER;
    long entered = 0;
    int new_pc = 0;
    const char *kept = NULL;
    Py_ssize_t kept_size = 0;
    if (answer != Py_None) {
        int parsed = op == FRAME_CALL ?
            (entered = PyLong_AsLong(answer), !(entered == -1 && PyErr_Occurred())) :
            PyArg_ParseTuple(answer, "liy#", &entered, &new_pc, &kept, &kept_size);
        if (!parsed) {
            Py_DECREF(answer);
            return -2;
        }
        Py_ssize_t kept_count = kept_size / (Py_ssize_t)sizeof(uint32_t);
        uint32_t *made = reserve(scratch->question, &scratch->question_capacity,
                                 sizeof(uint32_t), 2 + kept_count);
        if (made == NULL) {
            Py_DECREF(answer);
            return -2;
        }
        scratch->question = made;
        made[0] = (uint32_t)entered;            /* (-1 and beyond: no context, checked) */
        made[1] = (uint32_t)new_pc;
        if (kept_count)
            memcpy(made + 2, kept, kept_count * sizeof(uint32_t));
        answer_id = vt_intern(&table->frame_answers, made, 2 + kept_count);
    }
    Py_DECREF(answer);
    if (answer_id == -1 && PyErr_Occurred())
        return -2;
    return vector32_push(&table->answer_of, answer_id) < 0 ? -2 : answer_id;
}

/* The successor of a step that changes the task's frames (``run->frame_op``): CALL pushes
 * the callee's frame (``enter_routine``), LEAVE pops the task's frame and its caller goes
 * on after the call (``leave_routine``).  The frames below the top are the context's:
 * Python gives the context entered (``called_context``, ``left_context``), and the
 * task's segment of the frame vector becomes the new top frame's pc and locals, projected.
 * ``task``'s frame starts at ``where`` in ``frame`` with ``locals`` values, at ``pc``.
 * VM_DONE (added to ``found``), VM_UNSUPPORTED (Python steps it), -1. */
static int frame_step(PackedTable *table, Scratch *scratch, Run *run, const int32_t *code,
                      Py_ssize_t task, int32_t where, int32_t locals, int32_t pc,
                      uint32_t context, const uint32_t *frame, Py_ssize_t frame_length,
                      int32_t data_id, Py_ssize_t data_length, Successors *found,
                      Int32Vector *changed)
{
    const int32_t *call = code + run->call_at;      /* (a call's only) */
    int32_t answer_id = entered_context(table, scratch, run->frame_op, context, task, pc,
                                        run->frame_op == FRAME_CALL ? call[0] : -1,
                                        frame + where + 1, locals);
    if (answer_id < 0)
        return answer_id == NO_ANSWER ? VM_UNSUPPORTED : -1;
    Py_ssize_t answer_length;
    const uint32_t *answer = vt_items(&table->frame_answers, answer_id, &answer_length);
    int64_t entered = answer[0];
    int32_t new_pc = (int32_t)answer[1];
    const uint32_t *kept = answer + 2;          /* the caller's locals (a return) */
    Py_ssize_t kept_count = answer_length - 2;
    if (entered < 0 || entered >= table->contexts)
        return VM_UNSUPPORTED;
    /* (the context tables may have moved: Python added a context) */
    const int32_t *info = table->context_tasks + (entered * table->task_count + task) * TASK_INFO;
    int32_t top = info[0], count = info[2];
    if (top < 0 || top >= table->routine_count ||
            info[1] != where || new_pc < 0 || new_pc >= table->routines[top].length ||
            (table->projecting && table->routines[top].code == NULL) ||
            (run->frame_op == FRAME_LEAVE && kept_count != count))
        return VM_UNSUPPORTED;
    Py_ssize_t length = frame_length - locals + count, after = where + 1 + locals;
    uint32_t *made = reserve(scratch->called, &scratch->called_capacity, sizeof(uint32_t),
                             length + 1);
    if (made == NULL)
        return -1;
    scratch->called = made;
    memcpy(made, frame, where * sizeof(uint32_t));
    made[0] = (uint32_t)entered;
    memcpy(made + where + 1 + count, frame + after, (frame_length - after) * sizeof(uint32_t));
    uint32_t *top_locals = made + where + 1;
    if (run->frame_op == FRAME_LEAVE)
        memcpy(top_locals, kept, kept_count * sizeof(uint32_t));
    if (run->frame_op == FRAME_CALL) {
        int32_t initial = call[1], arguments = call[2 + initial];
        const int32_t *params = call + 3 + initial;
        if (initial != count)
            return VM_UNSUPPORTED;
        memcpy(top_locals, call + 2, count * sizeof(uint32_t));
        for (int32_t k = 0; k < arguments; k++) {
            int32_t slot = params[2 * k];
            if (slot < 0 || slot >= count)
                return VM_UNSUPPORTED;
            int32_t id = store_id(table, run->temps[k]);
            if (id < 0)
                return -1;
            top_locals[slot] = (uint32_t)id;
        }
        for (int32_t k = 0; k < count; k++)
            if (top_locals[k] == (uint32_t)-1)
                return VM_UNSUPPORTED;      /* (a parameter without its argument) */
    }
    int32_t pc_id = number_id(table, T_INT, (double)new_pc, NULL);
    if (pc_id < 0)
        return -1;
    made[where] = (uint32_t)pc_id;
    if (table->projecting) {
        run->locals = top_locals;
        run->local_count = count;
        run->pc = new_pc;
        project(table, &table->routines[top], (uint32_t)entered, run);
    }
    int32_t new_frame = vt_intern(&table->frames, made, length);
    int32_t new_data = new_frame < 0 ? -1 : !run->data_changed ? data_id :
        data_intern(table, run->data, data_length);
    if (new_data < 0 || add_successor(found, new_frame, new_data) < 0 ||
            vector32_push(changed, 1) < 0)
        return -1;
    return VM_DONE;
}

/* One task's instruction in a state of several tasks, by the machine: the block at its pc
 * once per choice script (tasks take turns one instruction each: no merged run), as
 * ``staged_step`` runs it through ``fused_step`` on a view of that task.  Its successors
 * are appended to ``found`` (``changed``: each one changes the state, but a wait's
 * idle step: ``scratch->waited``).  VM_UNSUPPORTED (with ``found`` as it was) where
 * Python must step the task: no block, an error, a step other than a wait's that leaves
 * the state as it is. */
static int task_machine_step(PackedTable *table, Scratch *scratch, const int32_t *info,
                             uint32_t context, const uint32_t *frame, Py_ssize_t frame_length,
                             int32_t data_id, const uint32_t *data, Py_ssize_t data_length,
                             Successors *found, Int32Vector *changed)
{
    int32_t routine_index = info[0], where = info[1], locals = info[2];
    if (!(info[3] & TASK_RUNS) || routine_index < 0 || routine_index >= table->routine_count ||
            where < 1 || where + 1 + locals > frame_length)
        return VM_UNSUPPORTED;
    Routine *routine = &table->routines[routine_index];
    uint32_t pc_id = frame[where];              /* (the pc as a value: an int) */
    if (pc_id >= table->values || table->value_tag[pc_id] != T_INT)
        return VM_UNSUPPORTED;
    int32_t start_pc = (int32_t)table->value_number[pc_id];
    if (routine->code == NULL || start_pc < 0 || start_pc >= routine->length ||
            routine->block_start[start_pc] < 0)
        return VM_UNSUPPORTED;
    Run run;
    if (start_run(&run, table, scratch, frame_length, data_length, context) < 0)
        return -1;
    uint32_t *work_frame = scratch->frame, *work_data = scratch->data;
    run.locals = work_frame + where + 1;
    run.local_count = locals;
    run.tasks = 1;
    Py_ssize_t found_before = found->count, ran_before = scratch->ran.length;
    Py_ssize_t waited_before = scratch->waited.length;
    Py_ssize_t pending_before = scratch->pending.length;
    int outcome = VM_DONE;
    for (;;) {
        memcpy(work_frame, frame, frame_length * sizeof(uint32_t));
        memcpy(work_data, data, data_length * sizeof(uint32_t));
        run.data_changed = run.locals_changed = 0;
        run.idle = 0;
        run.frame_op = FRAME_KEPT;
        run.pc = start_pc;
        run.size_count = 0;
        run.epoch = ++scratch->epoch;
        Py_ssize_t ran_here = scratch->ran.length;
        if (note_ran(table, scratch, routine_index, start_pc) < 0)
            return -1;
        outcome = execute(&run, routine->code, routine->block_start[start_pc], NULL);
        scratch->epoch = run.epoch;
        if (outcome < 0)
            return -1;
        if (outcome == VM_DONE && run.frame_op != FRAME_KEPT) {
            Py_ssize_t task = (info - table->context_tasks) / TASK_INFO -
                (Py_ssize_t)context * table->task_count;
            outcome = frame_step(table, scratch, &run, routine->code, task, where, locals,
                                 start_pc, context, frame, frame_length, data_id, data_length,
                                 found, changed);
            if (outcome < 0)
                return -1;
            if (outcome == VM_DONE)
                return VM_DONE;
            break;
        }
        if (outcome != VM_DONE || run.pc < 0 || run.pc >= routine->length ||
                (run.pc == start_pc && !run.locals_changed && !run.data_changed &&
                 !run.idle)) {
            outcome = VM_UNSUPPORTED;
            break;
        }
        if (run.idle) {
            /* (its line counts as run only if the idle step is kept: tasks_step) */
            forget_ran(table, scratch, ran_here);
            if (vector32_push(&scratch->waited, (int32_t)found->count) < 0 ||
                    vector32_push(&scratch->waited, routine_index) < 0 ||
                    vector32_push(&scratch->waited, start_pc) < 0)
                return -1;
        }
        if (table->projecting)
            project(table, routine, context, &run);
        int32_t new_pc = run.pc == start_pc ? (int32_t)pc_id :
            number_id(table, T_INT, (double)run.pc, NULL);
        if (new_pc < 0)
            return -1;
        work_frame[where] = (uint32_t)new_pc;
        int32_t new_frame = vt_intern(&table->frames, work_frame, frame_length);
        int32_t new_data = new_frame < 0 ? -1 : !run.data_changed ? data_id :
            data_intern(table, work_data, data_length);
        if (new_data < 0 || add_successor(found, new_frame, new_data) < 0 ||
                vector32_push(changed, !run.idle) < 0)
            return -1;
        if (run.size_count == 0 || !next_script(&run))
            return VM_DONE;
    }
    found->count = found_before;
    changed->length = found_before;
    scratch->waited.length = waited_before;
    forget_ran(table, scratch, ran_before);
    scratch->pending.length = pending_before;
    return outcome;
}

/* One task's transitions in state ``id`` from Python (``python_task_successors``),
 * appended to ``found``: 0, VM_UNSUPPORTED (Python steps the whole state), -1 */
static int task_python_step(PackedTable *table, Py_ssize_t id, Py_ssize_t task,
                            Successors *found, Int32Vector *changed)
{
    PyObject *answer = PyObject_CallMethod((PyObject *)table, "python_task_successors", "nn",
                                           id, task);
    if (answer == NULL)
        return -1;
    if (answer == Py_None) {
        Py_DECREF(answer);
        return VM_UNSUPPORTED;
    }
    PyObject *fast = PySequence_Fast(answer, "python_task_successors must give a sequence");
    Py_DECREF(answer);
    if (fast == NULL)
        return -1;
    for (Py_ssize_t i = 0; i < PySequence_Fast_GET_SIZE(fast); i++) {
        int frame, data, moved;
        if (!PyArg_ParseTuple(PySequence_Fast_GET_ITEM(fast, i), "iip", &frame, &data, &moved)
                || add_successor(found, frame, data) < 0 || vector32_push(changed, moved) < 0) {
            Py_DECREF(fast);
            return -1;
        }
    }
    Py_DECREF(fast);
    return 0;
}

/* the ORDER_ flags of ``task``'s instruction ``pc`` of ``routine`` (0: none known) */
static inline int order_flags(PackedTable *table, Py_ssize_t task, int32_t routine, int64_t pc)
{
    if (table->order_offsets == NULL || routine < 0 || routine >= table->order_routines)
        return 0;
    Py_ssize_t at = task * table->order_routines + routine;
    int64_t offset = table->order_offsets[at];
    if (offset < 0 || pc < 0 || pc >= table->order_lengths[at])
        return 0;
    return table->order_flags[offset + pc];
}

/* the program counter of the task whose frame starts at ``where`` in frame segment
 * ``frame_id`` (-1: not a pc) */
static int64_t task_pc(PackedTable *table, int32_t frame_id, int32_t where)
{
    Py_ssize_t length;
    const uint32_t *frame = vt_items(&table->frames, frame_id, &length);
    if (where < 1 || where >= length)
        return -1;
    uint32_t pc_id = frame[where];
    if (pc_id >= table->values || table->value_tag[pc_id] != T_INT)
        return -1;
    return (int64_t)table->value_number[pc_id];
}

/* One step of the task ``info`` describes from the segments (frame_id, data_id), not a
 * stored state, into ``scratch->probe``: the machine's outcome */
static int probe_step(PackedTable *table, Scratch *scratch, const int32_t *info,
                      uint32_t context, int32_t frame_id, int32_t data_id)
{
    Py_ssize_t frame_length, data_length;
    const uint32_t *frame = vt_items(&table->frames, frame_id, &frame_length);
    const uint32_t *data = data_items(table, data_id, &data_length);
    uint32_t *source = reserve(scratch->probe_source, &scratch->probe_capacity,
                               sizeof(uint32_t), frame_length + data_length + 1);
    if (source == NULL)
        return -1;
    scratch->probe_source = source;
    memcpy(source, frame, frame_length * sizeof(uint32_t));
    memcpy(source + frame_length, data, data_length * sizeof(uint32_t));
    scratch->probe.count = scratch->probe_changed.length = 0;
    return task_machine_step(table, scratch, info, context, source, frame_length, data_id,
                             source + frame_length, data_length, &scratch->probe,
                             &scratch->probe_changed);
}

/* A machine step of ``task`` run on through its merged local instructions, as
 * ``reduction.local_runs`` runs it: while the next instruction is mergeable and has one
 * transition that keeps running, ERRNO and the modes of the task's frames, and changes
 * the state.  The machine's steps keep the first three, and each one it takes changes the
 * state; its own calls and returns (``frame_step``) push a normal frame or pop the top
 * one and keep the modes of the frames below, so a run goes on through them as
 * ``_went_on`` lets it.  VM_DONE (the successor's segments updated), VM_UNSUPPORTED (the
 * machine does not take a step on the way: Python decides), -1. */
static int run_on(PackedTable *table, Scratch *scratch, Py_ssize_t task, int32_t *frame_id,
                  int32_t *data_id)
{
    for (;;) {
        /* (the context of the step's target: a call or a return changes it) */
        uint32_t context;
        const int32_t *info = task_info_at(table, *frame_id, task, &context);
        int64_t pc = task_pc(table, *frame_id, info[1]);
        if (info[0] < 0 || !(order_flags(table, task, info[0], pc) & ORDER_MERGEABLE))
            return VM_DONE;
        int outcome = probe_step(table, scratch, info, context, *frame_id, *data_id);
        if (outcome != VM_DONE)
            return outcome;
        if (scratch->probe.count != 1)
            return VM_DONE;
        uint32_t reached;
        task_info_at(table, scratch->probe.frames[0], task, &reached);
        table->run_frame_steps += reached != context;
        *frame_id = scratch->probe.frames[0];
        *data_id = scratch->probe.data[0];
    }
}

/* Every running task's transitions (``all_tasks_step``, the steps of the machine run on
 * through their local instructions when reduced), in task order, idle steps dropped:
 * ``found``, with ``scratch->owners`` (the task of each, + TASK_COUNT_MAX when Python's)
 * and ``scratch->changed`` (per transition before the idle ones were dropped: 0 the
 * machine's, 1 Python's and dropped, 2 Python's and kept); ``*before_drop``: their
 * count before.  VM_UNSUPPORTED: Python steps the whole state. */
static int all_tasks_step(PackedTable *table, Py_ssize_t id, Scratch *scratch,
                          Successors *found, Py_ssize_t *before_drop)
{
    Stored at;
    stored_state(table, id, &at);
    uint32_t context = at.frame[0];
    Py_ssize_t tasks = table->task_count;
    if (!(table->context_runs[context] & CONTEXT_RUNS) || table->context_tasks == NULL)
        return VM_UNSUPPORTED;
    const uint32_t *frame, *data;
    if (copy_source(scratch, at.frame, at.frame_length, at.data, at.data_length,
                    &frame, &data) < 0)
        return -1;
    Int32Vector *changed = &scratch->changed, *owners = &scratch->owners;
    found->count = changed->length = owners->length = scratch->waited.length = 0;
    long long by_machine = 0, by_python = 0, running = 0;
    for (Py_ssize_t task = 0; task < tasks; task++)
        running += table->context_tasks[(context * tasks + task) * TASK_INFO] >= 0;
    for (Py_ssize_t task = 0; task < tasks; task++) {
        /* (looked up again each time: Python may add contexts, which moves the array) */
        const int32_t *info = table->context_tasks + (context * tasks + task) * TASK_INFO;
        if (info[0] < 0)
            continue;                           /* (ended) */
        Py_ssize_t before = found->count, ran_before = scratch->ran.length;
        Py_ssize_t waited_before = scratch->waited.length;
        int outcome = task_machine_step(table, scratch, info, context, frame, at.frame_length,
                                        at.data_id, data, at.data_length, found, changed);
        if (outcome < 0)
            return -1;
        int owner = (int)task;
        for (Py_ssize_t i = before; outcome == VM_DONE && table->reduced && i < found->count;
             i++) {
            outcome = run_on(table, scratch, task, &found->frames[i], &found->data[i]);
            if (outcome < 0)
                return -1;
            info = table->context_tasks + (context * tasks + task) * TASK_INFO;
        }
        if (outcome == VM_DONE)
            by_machine++;
        else {
            /* Python steps this task (a step on the way of its run is Python's: the whole
             * run is then taken there) */
            found->count = before;
            changed->length = before;
            scratch->waited.length = waited_before;
            forget_ran(table, scratch, ran_before);
            owner += TASK_COUNT_MAX;            /* (Python's step) */
            outcome = task_python_step(table, id, task, found, changed);
            if (outcome < 0)
                return -1;
            if (outcome == VM_UNSUPPORTED) {
                table->task_python_steps += running;
                return VM_UNSUPPORTED;
            }
            by_python++;
        }
        for (Py_ssize_t i = before; i < found->count; i++)
            if (vector32_push(owners, owner) < 0)
                return -1;
    }
    /* idle steps dropped: kept when no task moves, or when each transition moves, or
     * when no task but its own moves */
    uint64_t moving = 0;
    int all_moved = 1;
    for (Py_ssize_t i = 0; i < found->count; i++) {
        if (changed->items[i])
            moving |= (uint64_t)1 << (owners->items[i] % TASK_COUNT_MAX);
        else
            all_moved = 0;
    }
    /* ``changed`` becomes, per successor, 0: the machine's, 1: Python's and dropped,
     * 2: Python's and kept */
    Py_ssize_t kept = 0, waited = 0;
    for (Py_ssize_t i = 0; i < found->count; i++) {
        int keep = !moving || all_moved || changed->items[i] ||
            !(moving & ~((uint64_t)1 << (owners->items[i] % TASK_COUNT_MAX)));
        changed->items[i] = owners->items[i] >= TASK_COUNT_MAX ? 1 + keep : 0;
        if (waited < scratch->waited.length && scratch->waited.items[waited] == i) {
            const int32_t *at = scratch->waited.items + waited;
            if (keep && note_ran(table, scratch, at[1], at[2]) < 0)
                return -1;
            waited += 3;
        }
        if (keep) {
            found->frames[kept] = found->frames[i];
            found->data[kept] = found->data[i];
            owners->items[kept++] = owners->items[i];
        }
    }
    *before_drop = found->count;
    found->count = kept;
    owners->length = kept;
    table->task_machine_steps += by_machine;
    table->task_python_steps += by_python;
    return VM_DONE;
}

/* Whether the machine's transition of ``task`` from state ``id`` into the segments
 * (frame_id, data_id) may be in an ample set, as ``PartialOrder._invisible_step`` decides
 * (its context is the state's: running, ERRNO, frames as they were): it changes the
 * state, its target was not numbered before the state, whose number is ``here`` (the
 * proviso), and the task can go on there.  1, 0, VM_UNSUPPORTED (Python decides: the machine does not take the task's
 * next step), -1. */
static int invisible_step(PackedTable *table, Scratch *scratch, Py_ssize_t id,
                          Py_ssize_t here, Py_ssize_t task, int32_t frame_id, int32_t data_id)
{
    int64_t key = index_key(&table->states, id);
    if (frame_id == (int32_t)(key >> 32) && data_id == (int32_t)(key & 0xffffffff))
        return 0;
    Py_ssize_t place = place_of(table, frame_id, data_id, 0);
    if (place == -2)
        return -1;
    if (place >= 0 && place <= here)
        return 0;                               /* (numbered before the state: C3) */
    uint32_t context;                           /* (the target's: a call changes it) */
    const int32_t *info = task_info_at(table, frame_id, task, &context);
    if (info[0] < 0)
        return VM_UNSUPPORTED;
    if (order_flags(table, task, info[0], task_pc(table, frame_id, info[1])) &
            ORDER_NEVER_WAITS)
        return 1;
    scratch->silent = 1;                        /* (a probe: nothing it runs is noted) */
    int outcome = probe_step(table, scratch, info, context, frame_id, data_id);
    scratch->silent = 0;
    if (outcome < 0)
        return -1;
    if (outcome != VM_DONE)
        return VM_UNSUPPORTED;
    for (Py_ssize_t i = 0; i < scratch->probe_changed.length; i++)
        if (scratch->probe_changed.items[i])
            return 1;                           /* (a step that moves: not a wait's try) */
    return 0;
}

/* The ample set of state ``id``, as ``PartialOrder.choose`` picks it, into ``found``: the
 * transitions of the first running task whose instruction is a candidate and each of
 * whose transitions (run on through its local instructions) is invisible.  Only that
 * task is stepped: the machine's steps always change the state, so no idle step of its
 * is dropped whatever the others do.  VM_DONE (found), NO_AMPLE (none: every task's
 * transitions are kept), VM_UNSUPPORTED (Python decides: a candidate the machine does
 * not step, or a probe it cannot take), -1.  Where it tries a choice it numbers the state
 * (``scratch->numbered``), as ``PartialOrder.ample`` does. */
enum { NO_AMPLE = 3 };

/* The observer is told the lines of the steps Python took at the state just stepped that
 * were kept (``note_python_spans``; ``kinds``: per successor 0 the machine's, 1 Python's
 * and dropped, 2 Python's and kept), and ``labels_wanted`` becomes whether it wants more.
 * 0 or -1. */
static int tell_python_spans(PackedTable *table, const Int32Vector *kinds, Py_ssize_t count)
{
    PyObject *answer = PyObject_CallMethod((PyObject *)table, "note_python_spans", "y#",
                                           (const char *)kinds->items,
                                           count * (Py_ssize_t)sizeof(int32_t));
    if (answer == NULL)
        return -1;
    table->labels_wanted = PyObject_IsTrue(answer);
    Py_DECREF(answer);
    return table->labels_wanted < 0 ? -1 : 0;
}

static int found_from_pairs(PyObject *pairs, Successors *found);

/* Whether the transitions of ``task`` at state ``id`` (numbered ``here``) are its ample
 * set, decided by Python (``python_task_ample``) where the machine does not take the
 * task's step: VM_DONE (``found``: the ample set), NO_AMPLE (they are not), VM_UNSUPPORTED
 * (Python steps the whole state), -1. */
static int task_python_ample(PackedTable *table, Py_ssize_t id, Py_ssize_t task,
                             Py_ssize_t here, Successors *found)
{
    PyObject *answer = PyObject_CallMethod((PyObject *)table, "python_task_ample", "nnn",
                                           id, task, here);
    if (answer == NULL)
        return -1;
    if (answer == Py_None || answer == Py_False) {
        Py_DECREF(answer);
        return answer == Py_None ? VM_UNSUPPORTED : NO_AMPLE;
    }
    int outcome = found_from_pairs(answer, found);
    Py_DECREF(answer);
    return outcome < 0 ? -1 : VM_DONE;
}

/* Whether ``task``'s instruction at state ``id``, not an ample candidate, is one there
 * because the tasks it conflicts with are held at their barriers (``python_held``,
 * ``barrier_holds``): 1, 0 or -1. */
static int task_python_held(PackedTable *table, Py_ssize_t id, Py_ssize_t task)
{
    PyObject *answer = PyObject_CallMethod((PyObject *)table, "python_held", "nn", id, task);
    if (answer == NULL)
        return -1;
    int held = PyObject_IsTrue(answer);
    Py_DECREF(answer);
    return held;
}

/* The ample set of a group of tasks at state ``id`` (numbered ``here``), decided by Python
 * (``python_group_ample``): VM_DONE (``found``), NO_AMPLE (none), -1. */
static int group_python_ample(PackedTable *table, Py_ssize_t id, Py_ssize_t here,
                              Successors *found)
{
    PyObject *answer = PyObject_CallMethod((PyObject *)table, "python_group_ample", "nn",
                                           id, here);
    if (answer == NULL)
        return -1;
    if (answer == Py_False) {
        Py_DECREF(answer);
        return NO_AMPLE;
    }
    int outcome = found_from_pairs(answer, found);
    Py_DECREF(answer);
    return outcome < 0 ? -1 : VM_DONE;
}

/* An ample set Python gave (``found``) is kept: counted, and the observer hears the lines
 * its transitions ran (each one kept).  0 or -1. */
static int python_ample_kept(PackedTable *table, Scratch *scratch, const Successors *found)
{
    table->task_python_steps++;
    scratch->changed.length = 0;
    for (Py_ssize_t i = 0; table->labels_wanted && i < found->count; i++)
        if (vector32_push(&scratch->changed, 2) < 0)
            return -1;
    if (table->labels_wanted && tell_python_spans(table, &scratch->changed, found->count) < 0)
        return -1;
    return 0;
}

static int ample_step(PackedTable *table, Py_ssize_t id, Scratch *scratch, Successors *found)
{
    Stored at;
    stored_state(table, id, &at);
    uint32_t context = at.frame[0];
    Py_ssize_t tasks = table->task_count, running = 0;
    if (!(table->context_runs[context] & CONTEXT_RUNS) || table->context_tasks == NULL)
        return VM_UNSUPPORTED;
    for (Py_ssize_t task = 0; task < tasks; task++)
        running += table->context_tasks[(context * tasks + task) * TASK_INFO] >= 0;
    if (running < 2)
        return NO_AMPLE;
    /* a choice is tried: the state is numbered first (``PartialOrder.ample``) */
    Py_ssize_t here = place_of(table, at.frame_id, at.data_id, 1);
    if (here < 0)
        return -1;
    scratch->numbered = 1;
    const uint32_t *frame, *data;
    if (copy_source(scratch, at.frame, at.frame_length, at.data, at.data_length,
                    &frame, &data) < 0)
        return -1;
    for (Py_ssize_t task = 0; task < tasks; task++) {
        const int32_t *info = table->context_tasks + (context * tasks + task) * TASK_INFO;
        int flags = info[0] < 0 ? 0 : order_flags(table, task, info[0],
                                                 task_pc(table, at.frame_id, info[1]));
        if (!(flags & ORDER_CANDIDATE)) {
            /* a candidate where the tasks it conflicts with are held (``barrier_holds``) */
            int held = flags & ORDER_HELD ? task_python_held(table, id, task) : 0;
            if (held < 0)
                return -1;
            if (!held)
                continue;
        }
        found->count = scratch->changed.length = scratch->pending.length = 0;
        scratch->defer = 1;
        scratch->defer_task = (int32_t)task;
        int outcome = task_machine_step(table, scratch, info, context, frame, at.frame_length,
                                        at.data_id, data, at.data_length, found,
                                        &scratch->changed);
        for (Py_ssize_t i = 0; outcome == VM_DONE && i < found->count; i++)
            outcome = run_on(table, scratch, task, &found->frames[i], &found->data[i]);
        scratch->defer = 0;
        int invisible = 1;
        for (Py_ssize_t i = 0; outcome == VM_DONE && invisible == 1 && i < found->count; i++)
            invisible = invisible_step(table, scratch, id, here, task, found->frames[i],
                                       found->data[i]);
        if (outcome == VM_DONE && invisible != 1 && invisible != 0)
            outcome = invisible;
        if (outcome != VM_DONE) {
            scratch->pending.length = 0;
            found->count = 0;
            if (outcome != VM_UNSUPPORTED)
                return outcome;
            /* the machine does not take the task's step or run: Python decides for it */
            outcome = task_python_ample(table, id, task, here, found);
            if (outcome == VM_DONE && python_ample_kept(table, scratch, found) < 0)
                return -1;
            if (outcome != NO_AMPLE)
                return outcome;
            continue;
        }
        if (invisible == 1) {
            for (Py_ssize_t i = 0; i + 2 < scratch->pending.length; i += 3)
                if (note_ran(table, scratch, scratch->pending.items[i],
                             scratch->pending.items[i + 1]) < 0)
                    return -1;
            scratch->pending.length = 0;
            table->task_machine_steps++;
            return VM_DONE;
        }
        scratch->pending.length = 0;
    }
    found->count = 0;
    /* no task alone: a group of the tasks whose next steps touch the same data
     * (``task_groups``), where some running task's instruction may be in one */
    int groups = 0;
    for (Py_ssize_t task = 0; task < tasks && !groups && running > 2; task++) {
        const int32_t *info = table->context_tasks + (context * tasks + task) * TASK_INFO;
        groups = info[0] >= 0 && (order_flags(table, task, info[0],
                                              task_pc(table, at.frame_id, info[1])) &
                                  ORDER_GROUPS);
    }
    if (!groups)
        return NO_AMPLE;
    int outcome = group_python_ample(table, id, here, found);
    if (outcome == VM_DONE && python_ample_kept(table, scratch, found) < 0)
        return -1;
    return outcome;
}

/* Where a choice was tried (``scratch->numbered``), the targets of the transitions kept
 * are numbered in order, each when it has none (``PartialOrder.ample``): an ample
 * transition then leads to a state numbered after its source.  VM_DONE or -1. */
static int number_targets(PackedTable *table, Scratch *scratch, Successors *found)
{
    for (Py_ssize_t i = 0; scratch->numbered && i < found->count; i++)
        if (place_of(table, found->frames[i], found->data[i], 1) < 0)
            return -1;
    return VM_DONE;
}

/* a row's count and offset in one int64 of row_at (rows of more successors, or beyond
 * that offset, are not kept: the state is stepped again) */
#define ROW_OFFSET_BITS 40
#define ROW_COUNT_LIMIT ((int64_t)1 << (62 - ROW_OFFSET_BITS))

/* The row kept for the state numbered ``place`` into ``found``: 1, or 0 (none kept), -1. */
static int row_recall(PackedTable *table, Py_ssize_t place, Successors *found)
{
    if (place >= table->row_at_capacity || table->row_at[place] < 0)
        return 0;
    int64_t at = table->row_at[place];
    const int64_t *row = table->row_keys + (at & (((int64_t)1 << ROW_OFFSET_BITS) - 1));
    int64_t count = at >> ROW_OFFSET_BITS;
    found->count = 0;
    for (int64_t i = 0; i < count; i++)
        if (add_successor(found, (int32_t)(row[i] >> 32), (int32_t)(row[i] & 0xffffffff)) < 0)
            return -1;
    return 1;
}

/* Keep ``found`` as the row of the state numbered ``place`` (once).  0 or -1. */
static int row_keep(PackedTable *table, Py_ssize_t place, const Successors *found)
{
    if (place >= table->row_at_capacity) {
        Py_ssize_t capacity = table->row_at_capacity;
        int64_t *at = reserve(table->row_at, &capacity, sizeof(int64_t), place + 1);
        if (at == NULL)
            return -1;
        for (Py_ssize_t i = table->row_at_capacity; i < capacity; i++)
            at[i] = -1;
        table->row_at = at;
        table->row_at_capacity = capacity;
    }
    if (table->row_at[place] >= 0 || found->count >= ROW_COUNT_LIMIT ||
            table->row_length + found->count >= ((int64_t)1 << ROW_OFFSET_BITS))
        return 0;
    int64_t *keys = reserve(table->row_keys, &table->row_capacity, sizeof(int64_t),
                            table->row_length + found->count);
    if (keys == NULL)
        return -1;
    table->row_keys = keys;
    table->row_at[place] = ((int64_t)found->count << ROW_OFFSET_BITS) | table->row_length;
    for (Py_ssize_t i = 0; i < found->count; i++)
        keys[table->row_length++] = state_key(found->frames[i], found->data[i]);
    return 0;
}

/* the number of stored state ``id`` (-1: none, -2: an error), where rows are kept: reduced
 * steps (kept also while an observer wants the lines steps run, and recalled only when
 * none does: a kept row names no lines) */
static Py_ssize_t row_place(PackedTable *table, Py_ssize_t id)
{
    if (!table->reduced)
        return -1;
    int64_t key = index_key(&table->states, id);
    return place_of(table, (int32_t)(key >> 32), (int32_t)(key & 0xffffffff), 0);
}

/* ``machine_step`` for a program of several tasks (``staged_step.staged_successors``
 * without interrupts, stored inputs or an environment): each running task's
 * instruction in task order, by the machine where it can and else by Python for that
 * task alone; then a task whose step changes nothing gives up its turn when another
 * can go on (``staged_step.idle_steps_dropped``); reduced (``set_order``), each of the
 * machine's steps runs on through its task's local instructions (a task whose step or
 * run the machine does not take is Python's, run on there) and the ample set of one task
 * is kept where there is one (Python deciding it for a candidate the machine does not
 * step, ``python_task_ample``).  VM_UNSUPPORTED: Python steps the whole state (a context
 * the machine does not run in, or Python asked for it: a task it cannot step alone, an
 * ample candidate with an idle step). */
static int tasks_step_anew(PackedTable *table, Py_ssize_t id, Scratch *scratch,
                           Successors *found);

/* ``tasks_step_anew``, or the row an earlier step of the state kept (reduced) */
static int tasks_step(PackedTable *table, Py_ssize_t id, Scratch *scratch, Successors *found)
{
    Py_ssize_t place = row_place(table, id);
    if (place == -2)
        return -1;
    int recalled = place >= 0 && !table->labels_wanted ? row_recall(table, place, found) : 0;
    if (recalled != 0) {
        table->rows_reused += recalled > 0;
        return recalled > 0 ? VM_DONE : -1;
    }
    int outcome = tasks_step_anew(table, id, scratch, found);
    if (outcome == VM_DONE && place == -1 && table->reduced)
        place = row_place(table, id);           /* (numbered by this step) */
    if (outcome == VM_DONE && place >= 0 && row_keep(table, place, found) < 0)
        return -1;
    return place == -2 ? -1 : outcome;
}

static int tasks_step_anew(PackedTable *table, Py_ssize_t id, Scratch *scratch,
                           Successors *found)
{
    scratch->numbered = 0;
    if (table->reduced) {
        int outcome = ample_step(table, id, scratch, found);
        if (outcome == VM_DONE)
            return number_targets(table, scratch, found);
        if (outcome != NO_AMPLE)
            return outcome;
    }
    Py_ssize_t before_drop = 0;
    scratch->defer = 0;
    int outcome = all_tasks_step(table, id, scratch, found, &before_drop);
    if (outcome != VM_DONE)
        return outcome;
    if (number_targets(table, scratch, found) < 0)
        return -1;
    Int32Vector *changed = &scratch->changed;
    int by_python = 0;
    for (Py_ssize_t i = 0; i < before_drop; i++)
        by_python |= changed->items[i] != 0;
    /* the observer hears the lines of Python's steps that were kept */
    if (by_python && table->labels_wanted && tell_python_spans(table, changed, before_drop) < 0)
        return -1;
    return VM_DONE;
}

/* The valuation ``index`` of state ``id``: VM_DONE (``*bits``), VM_UNSUPPORTED, -1. */
static int machine_valuation(PackedTable *table, Py_ssize_t index, Py_ssize_t id,
                             Scratch *scratch, uint64_t *bits)
{
    int64_t key = index_key(&table->states, id);
    Py_ssize_t frame_length, data_length;
    const uint32_t *frame = vt_items(&table->frames, (int32_t)(key >> 32), &frame_length);
    const uint32_t *data = data_items(table, (int32_t)(key & 0xffffffff), &data_length);
    Run run;
    run.table = table;
    run.locals = (uint32_t *)frame + 2;        /* (atoms read global data only) */
    run.local_count = frame_length >= 2 ? frame_length - 2 : 0;
    run.data = (uint32_t *)data;
    run.io = context_signals(table, frame[0]);
    run.lazy = 0;
    run.script_length = run.size_count = 0;
    run.chosen_epoch = scratch->chosen_epoch;
    run.chosen_value = scratch->chosen_value;
    run.epoch = ++scratch->epoch;
    *bits = 0;
    int outcome = execute(&run, table->valuations[index].code, 0, bits);
    return outcome < 0 ? -1 : outcome;
}

/* ================================================================ Python methods */

static PyObject *PackedTable_new(PyTypeObject *type, PyObject *args, PyObject *kwargs)
{
    PackedTable *self = (PackedTable *)type->tp_alloc(type, 0);
    if (self == NULL)
        return NULL;
    self->object_ids = PyDict_New();
    self->states.slots = new_slots(FIRST_CAPACITY);
    self->value_slots = new_slots(FIRST_CAPACITY);
    if (self->object_ids == NULL || self->states.slots == NULL || self->value_slots == NULL ||
            vt_init(&self->frames) < 0 || vt_init(&self->data) < 0 || vt_init(&self->spare) < 0 ||
            vt_init(&self->signals) < 0 || vt_init(&self->frame_questions) < 0 ||
            vt_init(&self->frame_answers) < 0) {
        Py_DECREF(self);
        return PyErr_Occurred() ? NULL : PyErr_NoMemory();
    }
    self->states.mask = self->value_mask = FIRST_CAPACITY - 1;
    return (PyObject *)self;
}

static int PackedTable_traverse(PackedTable *self, visitproc visit, void *arg)
{
    Py_VISIT(self->object_ids);
    for (Py_ssize_t i = 0; i < self->values; i++)
        Py_VISIT(self->value_object[i]);
    for (Py_ssize_t i = 0; i < ID_CACHE; i++)
        Py_VISIT(self->id_cache_object[i]);
    for (Py_ssize_t i = 0; self->item_memo_object != NULL && i < ITEM_MEMO; i++)
        Py_VISIT(self->item_memo_object[i]);
    return 0;
}

static int PackedTable_clear(PackedTable *self)
{
    Py_CLEAR(self->object_ids);
    for (Py_ssize_t i = 0; i < self->values; i++)
        Py_CLEAR(self->value_object[i]);
    for (Py_ssize_t i = 0; i < ID_CACHE; i++)
        Py_CLEAR(self->id_cache_object[i]);
    for (Py_ssize_t i = 0; self->item_memo_object != NULL && i < ITEM_MEMO; i++)
        Py_CLEAR(self->item_memo_object[i]);
    return 0;
}

static void free_program(PackedTable *self)
{
    for (Py_ssize_t i = 0; i < self->routine_count; i++) {
        Routine *r = &self->routines[i];
        PyMem_Free(r->kinds);
        PyMem_Free(r->first_visible);
        PyMem_Free(r->block_start);
        PyMem_Free(r->code);
        PyMem_Free(r->reset_offsets);
        PyMem_Free(r->reset_pairs);
        PyMem_Free(r->executed);
    }
    PyMem_Free(self->routines);
    self->routines = NULL;
    self->routine_count = 0;
    if (self->lazy_domain != NULL)
        for (Py_ssize_t i = 0; i < self->io_length; i++)
            PyMem_Free(self->lazy_domain[i]);
    PyMem_Free(self->lazy_domain);
    PyMem_Free(self->lazy_size);
    self->lazy_domain = NULL;
    self->lazy_size = NULL;
    for (Py_ssize_t i = 0; i < self->valuation_count; i++)
        PyMem_Free(self->valuations[i].code);
    PyMem_Free(self->valuations);
    self->valuations = NULL;
    self->valuation_count = 0;
    PyMem_Free(self->global_resets.offsets);
    PyMem_Free(self->global_resets.pairs);
    PyMem_Free(self->main_resets.offsets);
    PyMem_Free(self->main_resets.pairs);
    if (self->scratch != NULL) {
        scratch_free(self->scratch);
        PyMem_Free(self->scratch);
        self->scratch = NULL;
    }
    memset(&self->global_resets, 0, sizeof(Resets));
    memset(&self->main_resets, 0, sizeof(Resets));
    self->projecting = 0;
}

static void select_states(PackedTable *self, PyObject *chosen);

static void PackedTable_dealloc(PackedTable *self)
{
    PyObject_GC_UnTrack(self);
    select_states(self, NULL);          /* (the selected set keeps its own index) */
    index_free(&self->places);
    PyMem_Free(self->row_at);
    PyMem_Free(self->row_keys);
    PackedTable_clear(self);
    PyMem_Free(self->item_memo_object);
    PyMem_Free(self->item_memo_hash);
    PyMem_Free(self->big_slots);
    PyMem_Free(self->big_hashes);
    PyMem_Free(self->big_sums);
    free_program(self);
    PyMem_Free(self->value_tag);
    PyMem_Free(self->value_number);
    PyMem_Free(self->value_object);
    PyMem_Free(self->value_slots);
    vt_free(&self->frames);
    vt_free(&self->data);
    vt_free(&self->spare);
    vt_free(&self->signals);
    vt_free(&self->frame_questions);
    vt_free(&self->frame_answers);
    vector32_free(&self->answer_of);
    PyMem_Free(self->context_io);
    vector32_free(&self->newly_executed);
    PyMem_Free(self->states.keys);
    PyMem_Free(self->states.slots);
    PyMem_Free(self->context_routine);
    PyMem_Free(self->context_runs);
    PyMem_Free(self->context_tasks);
    PyMem_Free(self->order_flags);
    PyMem_Free(self->order_offsets);
    PyMem_Free(self->order_lengths);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* ``value_ids(values) -> bytes``: the ids of a sequence of values, as 32-bit numbers */
static PyObject *PackedTable_value_ids(PackedTable *self, PyObject *values)
{
    PyObject *fast = PySequence_Fast(values, "value_ids takes a sequence");
    if (fast == NULL)
        return NULL;
    Py_ssize_t length = PySequence_Fast_GET_SIZE(fast);
    PyObject *result = PyBytes_FromStringAndSize(NULL, length * sizeof(uint32_t));
    if (result == NULL) {
        Py_DECREF(fast);
        return NULL;
    }
    uint32_t *ids = (uint32_t *)PyBytes_AS_STRING(result);
    for (Py_ssize_t i = 0; i < length; i++) {
        int32_t id = value_id(self, PySequence_Fast_GET_ITEM(fast, i));
        if (id < 0) {
            Py_DECREF(fast);
            Py_DECREF(result);
            return NULL;
        }
        ids[i] = (uint32_t)id;
    }
    Py_DECREF(fast);
    return result;
}

/* ``values(ids: bytes) -> tuple``: the values of 32-bit ids */
static PyObject *values_of(PackedTable *self, const uint32_t *ids, Py_ssize_t length)
{
    PyObject *result = PyTuple_New(length);
    if (result == NULL)
        return NULL;
    for (Py_ssize_t i = 0; i < length; i++) {
        if (ids[i] >= (uint32_t)self->values) {
            Py_DECREF(result);
            PyErr_SetString(PyExc_IndexError, "no such value id");
            return NULL;
        }
        PyObject *object = value_object(self, (int32_t)ids[i]);
        if (object == NULL) {
            Py_DECREF(result);
            return NULL;
        }
        PyTuple_SET_ITEM(result, i, object);
    }
    return result;
}

static PyObject *PackedTable_values(PackedTable *self, PyObject *ids)
{
    char *buffer;
    Py_ssize_t size;
    if (PyBytes_AsStringAndSize(ids, &buffer, &size) < 0)
        return NULL;
    return values_of(self, (const uint32_t *)buffer, size / (Py_ssize_t)sizeof(uint32_t));
}

/* ``add_context(routine, flags, signals) -> id``: a new context and what the machine
 * needs of it (flags: CONTEXT_ values; signals: the value ids of the signals) */
static PyObject *PackedTable_add_context(PackedTable *self, PyObject *args)
{
    int routine, runs;
    Py_buffer io, tasks = {0};
    if (ensure_index(self) < 0 ||
            !PyArg_ParseTuple(args, "iiy*|y*", &routine, &runs, &io, &tasks))
        return NULL;
    if (tasks.buf != NULL) {
        Py_ssize_t numbers = tasks.len / (Py_ssize_t)sizeof(int32_t);
        int wrong = self->task_count < 2 || numbers != self->task_count * TASK_INFO;
        int32_t *all = wrong ? NULL : reserve(self->context_tasks,
                                              &self->context_tasks_capacity,
                                              numbers * sizeof(int32_t), self->contexts + 1);
        if (!wrong && all != NULL) {
            self->context_tasks = all;
            memcpy(all + self->contexts * numbers, tasks.buf, numbers * sizeof(int32_t));
        }
        PyBuffer_Release(&tasks);
        if (wrong || all == NULL) {
            PyBuffer_Release(&io);
            return wrong ? PyErr_Format(PyExc_ValueError, "task_info: %zd tasks of %d numbers",
                                        self->task_count, TASK_INFO) : PyErr_NoMemory();
        }
    }
    else if (self->task_count > 1) {
        PyBuffer_Release(&io);
        return PyErr_Format(PyExc_ValueError, "a context of several tasks needs its tasks");
    }
    int32_t io_id = vt_intern(&self->signals, io.buf, io.len / sizeof(uint32_t));
    PyBuffer_Release(&io);
    if (io_id < 0)
        return NULL;
    Py_ssize_t io_capacity = self->context_capacity;
    int32_t *ios = reserve(self->context_io, &io_capacity, sizeof(int32_t), self->contexts + 1);
    if (ios == NULL)
        return NULL;
    self->context_io = ios;
    self->context_io[self->contexts] = io_id;
    Py_ssize_t capacity = self->context_capacity;
    int32_t *routines = reserve(self->context_routine, &capacity, sizeof(int32_t),
                                self->contexts + 1);
    if (routines == NULL)
        return NULL;
    self->context_routine = routines;
    capacity = self->context_capacity;
    uint8_t *flags = reserve(self->context_runs, &capacity, 1, self->contexts + 1);
    if (flags == NULL)
        return NULL;
    self->context_runs = flags;
    self->context_capacity = capacity;
    self->context_routine[self->contexts] = routine;
    self->context_runs[self->contexts] = (uint8_t)runs;
    return PyLong_FromSsize_t(self->contexts++);
}

/* ``intern_vectors(frame: bytes, data: bytes, add) -> (id, new)`` (id -1: new, not added) */
static PyObject *PackedTable_intern_vectors(PackedTable *self, PyObject *args)
{
    Py_buffer frame, data;
    int add = 1;
    if (ensure_index(self) < 0 || !PyArg_ParseTuple(args, "y*y*|p", &frame, &data, &add))
        return NULL;
    PyObject *result = NULL;
    int32_t frame_id = vt_intern(&self->frames, frame.buf, frame.len / sizeof(uint32_t));
    int32_t data_id = frame_id < 0 ? -1 :
        vt_intern(&self->data, data.buf, data.len / sizeof(uint32_t));
    if (data_id >= 0) {
        int is_new = 0;
        Py_ssize_t id = intern_key(self, frame_id, data_id, add, &is_new);
        if (id != -2)
            result = Py_BuildValue("(nO)", id, is_new ? Py_True : Py_False);
    }
    PyBuffer_Release(&frame);
    PyBuffer_Release(&data);
    return result;
}

/* 0 when ``frame_id`` and ``data_id`` name stored segments, else -1 and IndexError */
static int check_part_ids(PackedTable *self, int32_t frame_id, int32_t data_id)
{
    int spare = data_id >= 0 && (data_id & SPARE);
    if (frame_id < 0 || frame_id >= self->frames.count || data_id < 0 ||
            (spare ? (data_id & ~SPARE) >= self->spare.count : data_id >= self->data.count)) {
        PyErr_SetString(PyExc_IndexError, "no such state part");
        return -1;
    }
    return 0;
}

/* (context, pc, locals, data values) of the segments ``frame_id`` and ``data_id`` */
/* the items of a frame segment and a data segment (-1 and IndexError: no such segment) */
static int segment_items(PackedTable *self, int32_t frame_id, int32_t data_id,
                         const uint32_t **frame, Py_ssize_t *frame_length,
                         const uint32_t **data, Py_ssize_t *data_length)
{
    if (check_part_ids(self, frame_id, data_id) < 0)
        return -1;
    *frame = vt_items(&self->frames, frame_id, frame_length);
    *data = data_items(self, data_id, data_length);
    return 0;
}

static PyObject *parts_of(PackedTable *self, int32_t frame_id, int32_t data_id)
{
    Py_ssize_t frame_length, data_length;
    const uint32_t *frame, *data;
    if (segment_items(self, frame_id, data_id, &frame, &frame_length, &data, &data_length) < 0)
        return NULL;
    PyObject *locals = values_of(self, frame + 2, frame_length - 2);
    PyObject *values = locals == NULL ? NULL : values_of(self, data, data_length);
    PyObject *result = values == NULL ? NULL :
        Py_BuildValue("(IIOO)", frame[0], frame[1], locals, values);
    Py_XDECREF(locals);
    Py_XDECREF(values);
    return result;
}

/* ``vectors(id) -> (context, pc, locals, data)``: a stored state's parts, the context
 * and pc as numbers, locals and data as tuples of values */
static PyObject *PackedTable_vectors(PackedTable *self, PyObject *argument)
{
    Py_ssize_t id = PyLong_AsSsize_t(argument);
    if (id == -1 && PyErr_Occurred())
        return NULL;
    if (id < 0 || id >= self->states.count) {
        PyErr_SetString(PyExc_IndexError, "no such state id");
        return NULL;
    }
    int64_t key = index_key(&self->states, id);
    return parts_of(self, (int32_t)(key >> 32), (int32_t)(key & 0xffffffff));
}

/* ``key(id) -> (frame id, data id, context id)``: a stored state's segments and context */
static PyObject *PackedTable_key(PackedTable *self, PyObject *argument)
{
    Py_ssize_t id = PyLong_AsSsize_t(argument);
    if (id == -1 && PyErr_Occurred())
        return NULL;
    if (id < 0 || id >= self->states.count)
        return PyErr_Format(PyExc_IndexError, "no such state id");
    int64_t key = index_key(&self->states, id);
    int32_t frame = (int32_t)(key >> 32);
    return Py_BuildValue("(iiI)", frame, (int32_t)(key & 0xffffffff),
                         self->frames.arena[self->frames.offsets[frame]]);
}

/* ``parts(frame id, data id)``: as ``vectors``, for segments not (yet) a stored state */
static PyObject *PackedTable_parts(PackedTable *self, PyObject *args)
{
    int frame, data;
    if (!PyArg_ParseTuple(args, "ii", &frame, &data))
        return NULL;
    return parts_of(self, frame, data);
}

/* ``intern_parts(frame: bytes, data: bytes) -> (frame id, data id)`` */
static PyObject *PackedTable_intern_parts(PackedTable *self, PyObject *args)
{
    Py_buffer frame, data;
    if (ensure_index(self) < 0 || !PyArg_ParseTuple(args, "y*y*", &frame, &data))
        return NULL;
    int32_t frame_id = vt_intern(&self->frames, frame.buf, frame.len / sizeof(uint32_t));
    int32_t data_id = frame_id < 0 ? -1 :
        data_intern(self, data.buf, data.len / sizeof(uint32_t));
    PyBuffer_Release(&frame);
    PyBuffer_Release(&data);
    if (data_id < 0)
        return NULL;
    return Py_BuildValue("(ii)", frame_id, data_id);
}

/* ``segments(frame id, data id) -> (frame, data)``: interned segments' vectors as bytes
 * (what ``intern_parts`` took): how a distributed search sends a successor the step
 * machine found without building its values */
static PyObject *PackedTable_segments(PackedTable *self, PyObject *args)
{
    int frame_id, data_id;
    if (!PyArg_ParseTuple(args, "ii", &frame_id, &data_id))
        return NULL;
    Py_ssize_t frame_length, data_length;
    const uint32_t *frame, *data;
    if (segment_items(self, frame_id, data_id, &frame, &frame_length, &data, &data_length) < 0)
        return NULL;
    return Py_BuildValue("(y#y#)", (const char *)frame,
                         (Py_ssize_t)(frame_length * (Py_ssize_t)sizeof(uint32_t)),
                         (const char *)data,
                         (Py_ssize_t)(data_length * (Py_ssize_t)sizeof(uint32_t)));
}

/* ``segments_batch(keys) -> (frames, data, lengths)``: ``segments`` of many states at once,
 * keys as bytes of uint64 ``frame id << 32 | data id``: their frame vectors end to end, their
 * data vectors end to end, and each frame vector's length (bytes of uint32): how a
 * distributed search writes a chunk of successors for their owners without a Python call
 * per successor */
static PyObject *PackedTable_segments_batch(PackedTable *self, PyObject *args)
{
    Py_buffer keys;
    if (!PyArg_ParseTuple(args, "y*", &keys))
        return NULL;
    const uint64_t *key = keys.buf;
    Py_ssize_t count = keys.len / (Py_ssize_t)sizeof(uint64_t);
    Py_ssize_t frame_total = 0, data_total = 0, length;
    PyObject *frames = NULL, *data = NULL, *lengths = NULL, *result = NULL;
    for (Py_ssize_t i = 0; i < count; i++) {
        int32_t frame_id = (int32_t)(key[i] >> 32), data_id = (int32_t)(key[i] & 0xFFFFFFFFu);
        if (check_part_ids(self, frame_id, data_id) < 0)
            goto done;
        vt_items(&self->frames, frame_id, &length);
        frame_total += length;
        data_items(self, data_id, &length);
        data_total += length;
    }
    frames = PyBytes_FromStringAndSize(NULL, frame_total * (Py_ssize_t)sizeof(uint32_t));
    data = PyBytes_FromStringAndSize(NULL, data_total * (Py_ssize_t)sizeof(uint32_t));
    lengths = PyBytes_FromStringAndSize(NULL, count * (Py_ssize_t)sizeof(uint32_t));
    if (frames == NULL || data == NULL || lengths == NULL)
        goto done;
    uint32_t *frame_out = (uint32_t *)PyBytes_AS_STRING(frames);
    uint32_t *data_out = (uint32_t *)PyBytes_AS_STRING(data);
    uint32_t *length_out = (uint32_t *)PyBytes_AS_STRING(lengths);
    for (Py_ssize_t i = 0; i < count; i++) {
        const uint32_t *items = vt_items(&self->frames, (int32_t)(key[i] >> 32), &length);
        memcpy(frame_out, items, length * sizeof(uint32_t));
        frame_out += length;
        length_out[i] = (uint32_t)length;
        items = data_items(self, (int32_t)(key[i] & 0xFFFFFFFFu), &length);
        memcpy(data_out, items, length * sizeof(uint32_t));
        data_out += length;
    }
    result = PyTuple_Pack(3, frames, data, lengths);
done:
    Py_XDECREF(frames);
    Py_XDECREF(data);
    Py_XDECREF(lengths);
    PyBuffer_Release(&keys);
    return result;
}

/* ``owners(keys, value_prints, context_prints, count, by_data) -> bytes of uint32``: the
 * owner of each key's state (keys as ``segments_batch`` takes them) among ``count`` workers
 * of a distributed search (check/distributed/codec.py, ``VectorCodec._owners_of``, which
 * computes the same with numpy): the fingerprints (uint64) of the values and contexts by
 * id mixed position by position, the frame's (its context, its pc, its locals) with one
 * constant and the data's with another, the two sums xor-ed (``by_data``: the data's
 * alone), splitmix64's finaliser, modulo ``count``.  In one call, where numpy's two dozen
 * array operations cost a round of a few hundred states more than the stepping's share */
static PyObject *PackedTable_owners(PackedTable *self, PyObject *args)
{
    Py_buffer keys, values, contexts;
    Py_ssize_t count;
    int by_data;
    if (!PyArg_ParseTuple(args, "y*y*y*np", &keys, &values, &contexts, &count, &by_data))
        return NULL;
    PyObject *result = NULL;
    const uint64_t *key = keys.buf, *value_print = values.buf, *context_print = contexts.buf;
    Py_ssize_t states = keys.len / (Py_ssize_t)sizeof(uint64_t);
    Py_ssize_t value_count = values.len / (Py_ssize_t)sizeof(uint64_t);
    Py_ssize_t context_count = contexts.len / (Py_ssize_t)sizeof(uint64_t);
    if (count < 1) {
        PyErr_SetString(PyExc_ValueError, "owners: no workers");
        goto done;
    }
    result = PyBytes_FromStringAndSize(NULL, states * (Py_ssize_t)sizeof(uint32_t));
    if (result == NULL)
        goto done;
    uint32_t *owner = (uint32_t *)PyBytes_AS_STRING(result);
    for (Py_ssize_t i = 0; i < states; i++) {
        int32_t frame_id = (int32_t)(key[i] >> 32), data_id = (int32_t)(key[i] & 0xFFFFFFFFu);
        Py_ssize_t frame_length, data_length;
        const uint32_t *frame, *data;
        if (segment_items(self, frame_id, data_id, &frame, &frame_length, &data,
                          &data_length) < 0)
            goto failed;
        uint64_t mixed = 0, data_mixed = 0;
        for (Py_ssize_t j = 0; j < data_length; j++) {
            if ((Py_ssize_t)data[j] >= value_count)
                goto unknown;
            data_mixed += value_print[data[j]] * (2 * (uint64_t)j + 1) * 0x94D049BB133111EBULL;
        }
        if (!by_data) {
            if (frame_length < 2 || (Py_ssize_t)frame[0] >= context_count)
                goto unknown;
            mixed = context_print[frame[0]] * 0xBF58476D1CE4E5B9ULL +
                (uint64_t)frame[1] * 0x9E3779B97F4A7C15ULL * 3 * 0xBF58476D1CE4E5B9ULL;
            for (Py_ssize_t j = 2; j < frame_length; j++) {
                if ((Py_ssize_t)frame[j] >= value_count)
                    goto unknown;
                mixed += value_print[frame[j]] * (2 * (uint64_t)j + 1) * 0xBF58476D1CE4E5B9ULL;
            }
        }
        owner[i] = (uint32_t)(mix64(by_data ? data_mixed : mixed ^ data_mixed) %
                              (uint64_t)count);
    }
    goto done;
unknown:
    PyErr_SetString(PyExc_IndexError, "owners: a value or context without a fingerprint");
failed:
    Py_CLEAR(result);
done:
    PyBuffer_Release(&keys);
    PyBuffer_Release(&values);
    PyBuffer_Release(&contexts);
    return result;
}

/* the state (frame id, data id) stored as item ``i`` of a batch: its id into ``ids`` (bytes
 * of int64), whether it was new into ``news`` (bytes of 0 and 1); 0 / -1 */
static int store_item(PackedTable *self, int32_t frame_id, int32_t data_id, PyObject *ids,
                      PyObject *news, Py_ssize_t i)
{
    int is_new = 0;
    Py_ssize_t id = intern_key(self, frame_id, data_id, 1, &is_new);
    if (id == -2)
        return -1;
    ((int64_t *)PyBytes_AS_STRING(ids))[i] = id;
    PyBytes_AS_STRING(news)[i] = (char)is_new;
    return 0;
}

/* ``intern_batch(frames, data, lengths) -> (ids, new)``: ``intern_vectors`` of many states
 * at once (the layout ``segments_batch`` writes; each data vector ``len(data) / states``
 * ids): their ids (bytes of int64) and whether each was new (bytes of 0 and 1), in order;
 * how a worker stores a received batch without a Python call per state */
static PyObject *PackedTable_intern_batch(PackedTable *self, PyObject *args)
{
    Py_buffer frames, data, lengths;
    if (ensure_index(self) < 0 ||
            !PyArg_ParseTuple(args, "y*y*y*", &frames, &data, &lengths))
        return NULL;
    PyObject *ids = NULL, *news = NULL, *result = NULL;
    Py_ssize_t count = lengths.len / (Py_ssize_t)sizeof(uint32_t);
    Py_ssize_t frame_total = frames.len / (Py_ssize_t)sizeof(uint32_t);
    Py_ssize_t data_total = data.len / (Py_ssize_t)sizeof(uint32_t);
    Py_ssize_t width = count ? data_total / count : 0;
    const uint32_t *length = lengths.buf;
    Py_ssize_t sum = 0;
    for (Py_ssize_t i = 0; i < count; i++)
        sum += length[i];
    if (sum != frame_total || width * count != data_total) {
        PyErr_SetString(PyExc_ValueError, "intern_batch: vectors and lengths disagree");
        goto done;
    }
    ids = PyBytes_FromStringAndSize(NULL, count * (Py_ssize_t)sizeof(int64_t));
    news = PyBytes_FromStringAndSize(NULL, count);
    if (ids == NULL || news == NULL)
        goto done;
    const uint32_t *frame = frames.buf, *row = data.buf;
    for (Py_ssize_t i = 0; i < count; i++) {
        int32_t frame_id = vt_intern(&self->frames, frame, length[i]);
        int32_t data_id = frame_id < 0 ? -1 : vt_intern(&self->data, row, width);
        if (data_id < 0 || store_item(self, frame_id, data_id, ids, news, i) < 0)
            goto done;
        frame += length[i];
        row += width;
    }
    result = PyTuple_Pack(2, ids, news);
done:
    Py_XDECREF(ids);
    Py_XDECREF(news);
    PyBuffer_Release(&frames);
    PyBuffer_Release(&data);
    PyBuffer_Release(&lengths);
    return result;
}

/* ``intern_keys(keys) -> (ids, new)``: the states of these keys (bytes of uint64, frame id
 * << 32 | data id of segments this table holds) stored: their ids (bytes of int64) and
 * whether each was new (bytes of 0 and 1), in order; how a worker stores the successors it
 * owns itself, whose segments its step interned already */
static PyObject *PackedTable_intern_keys(PackedTable *self, PyObject *args)
{
    Py_buffer keys;
    if (ensure_index(self) < 0 || !PyArg_ParseTuple(args, "y*", &keys))
        return NULL;
    PyObject *ids = NULL, *news = NULL, *result = NULL;
    const uint64_t *key = keys.buf;
    Py_ssize_t count = keys.len / (Py_ssize_t)sizeof(uint64_t);
    ids = PyBytes_FromStringAndSize(NULL, count * (Py_ssize_t)sizeof(int64_t));
    news = PyBytes_FromStringAndSize(NULL, count);
    if (ids == NULL || news == NULL)
        goto done;
    for (Py_ssize_t i = 0; i < count; i++) {
        int32_t frame_id = (int32_t)(key[i] >> 32), data_id = (int32_t)(key[i] & 0xFFFFFFFFu);
        if (check_part_ids(self, frame_id, data_id) < 0 ||
                (data_id = settled_data(self, data_id)) < 0)
            goto done;
        if (store_item(self, frame_id, data_id, ids, news, i) < 0)
            goto done;
    }
    result = PyTuple_Pack(2, ids, news);
done:
    Py_XDECREF(ids);
    Py_XDECREF(news);
    PyBuffer_Release(&keys);
    return result;
}

/* ``resets``: None, or (offsets: bytes of int32, pairs: bytes of int32) */
static int parse_resets(PyObject *resets, int32_t **offsets, int32_t **pairs,
                        Py_ssize_t *lists)
{
    *offsets = *pairs = NULL;
    *lists = 0;
    if (resets == Py_None)
        return 0;
    const char *offset_bytes, *pair_bytes;
    Py_ssize_t offsets_size, pairs_size;
    if (!PyArg_ParseTuple(resets, "y#y#", &offset_bytes, &offsets_size, &pair_bytes,
                          &pairs_size))
        return -1;
    *offsets = PyMem_Malloc(offsets_size + sizeof(int32_t));
    *pairs = PyMem_Malloc(pairs_size + sizeof(int32_t));
    if (*offsets == NULL || *pairs == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    memcpy(*offsets, offset_bytes, offsets_size);
    memcpy(*pairs, pair_bytes, pairs_size);
    *lists = offsets_size / (Py_ssize_t)sizeof(int32_t) - 1;
    return 0;
}

/* ``set_program(store_length, io_length, routines, lazy, valuations)``:
 * routines: list of None or (kinds: bytes, first_visible: bytes, block_start: bytes of
 * int32, code: bytes of int32); lazy: {signal index: bytes of domain value ids};
 * valuations: list of bytes of int32 (atom code); projection: None or (global resets,
 * main's resets by pc or None, {routine: its resets by pc}), each resets list as
 * (offsets, pairs) (see ``parse_resets``). */
static PyObject *PackedTable_set_program(PackedTable *self, PyObject *args)
{
    Py_ssize_t store_length, io_length;
    PyObject *routines, *lazy, *valuations, *projection = Py_None;
    if (!PyArg_ParseTuple(args, "nnO!O!O!|O", &store_length, &io_length, &PyList_Type,
                          &routines, &PyDict_Type, &lazy, &PyList_Type, &valuations,
                          &projection))
        return NULL;
    free_program(self);
    self->store_length = store_length;
    self->io_length = io_length;
    Py_ssize_t count = PyList_GET_SIZE(routines);
    self->routines = PyMem_Calloc(count ? count : 1, sizeof(Routine));
    self->lazy_domain = PyMem_Calloc(io_length ? io_length : 1, sizeof(int32_t *));
    self->lazy_size = PyMem_Calloc(io_length ? io_length : 1, sizeof(int32_t));
    Py_ssize_t valuation_count = PyList_GET_SIZE(valuations);
    self->valuations = PyMem_Calloc(valuation_count ? valuation_count : 1, sizeof(Valuation));
    if (self->routines == NULL || self->lazy_domain == NULL || self->lazy_size == NULL ||
            self->valuations == NULL)
        return PyErr_NoMemory();
    self->routine_count = count;
    self->valuation_count = valuation_count;
    for (Py_ssize_t i = 0; i < count; i++) {
        PyObject *entry = PyList_GET_ITEM(routines, i);
        if (entry == Py_None)
            continue;
        const char *kinds, *visible, *starts, *code;
        Py_ssize_t kinds_length, visible_length, starts_length, code_length;
        if (!PyArg_ParseTuple(entry, "y#y#y#y#", &kinds, &kinds_length, &visible,
                              &visible_length, &starts, &starts_length, &code, &code_length))
            return NULL;
        Routine *r = &self->routines[i];
        r->length = kinds_length;
        if (visible_length != kinds_length ||
                starts_length != kinds_length * (Py_ssize_t)sizeof(int32_t)) {
            PyErr_SetString(PyExc_ValueError, "set_program: routine tables differ in length");
            return NULL;
        }
        r->kinds = PyMem_Malloc(kinds_length + 1);
        r->first_visible = PyMem_Malloc(kinds_length + 1);
        r->block_start = PyMem_Malloc(starts_length + 1);
        r->code = PyMem_Malloc(code_length + sizeof(int32_t));
        if (r->kinds == NULL || r->first_visible == NULL || r->block_start == NULL ||
                r->code == NULL)
            return PyErr_NoMemory();
        memcpy(r->kinds, kinds, kinds_length);
        memcpy(r->first_visible, visible, kinds_length);
        memcpy(r->block_start, starts, starts_length);
        memcpy(r->code, code, code_length);
        r->code_length = code_length / sizeof(int32_t);
        r->executed = PyMem_Calloc(kinds_length + 1, 1);
        if (r->executed == NULL)
            return PyErr_NoMemory();
    }
    if (projection != Py_None) {
        PyObject *global, *main, *frames;
        if (!PyArg_ParseTuple(projection, "OOO!", &global, &main, &PyDict_Type, &frames))
            return NULL;
        Py_ssize_t lists;
        if (parse_resets(global, &self->global_resets.offsets, &self->global_resets.pairs,
                         &self->global_resets.lists) < 0 ||
            parse_resets(main, &self->main_resets.offsets, &self->main_resets.pairs,
                         &self->main_resets.lists) < 0)
            return NULL;
        PyObject *key, *value;
        Py_ssize_t position = 0;
        while (PyDict_Next(frames, &position, &key, &value)) {
            Py_ssize_t index = PyLong_AsSsize_t(key);
            if (index == -1 && PyErr_Occurred())
                return NULL;
            if (index < 0 || index >= count || self->routines[index].code == NULL)
                continue;      /* (a routine the machine does not step: Python resets it) */
            Routine *r = &self->routines[index];
            if (parse_resets(value, &r->reset_offsets, &r->reset_pairs, &lists) < 0)
                return NULL;
            if (lists != r->length) {
                PyErr_SetString(PyExc_ValueError, "set_program: resets per pc differ in length");
                return NULL;
            }
        }
        self->projecting = 1;
    }
    PyObject *key, *value;
    Py_ssize_t position = 0;
    while (PyDict_Next(lazy, &position, &key, &value)) {
        Py_ssize_t index = PyLong_AsSsize_t(key);
        char *ids;
        Py_ssize_t size;
        if ((index == -1 && PyErr_Occurred()) || PyBytes_AsStringAndSize(value, &ids, &size) < 0)
            return NULL;
        if (index < 0 || index >= io_length || size == 0) {
            PyErr_SetString(PyExc_ValueError, "set_program: bad lazy input");
            return NULL;
        }
        self->lazy_domain[index] = PyMem_Malloc(size);
        if (self->lazy_domain[index] == NULL)
            return PyErr_NoMemory();
        memcpy(self->lazy_domain[index], ids, size);
        self->lazy_size[index] = (int32_t)(size / sizeof(int32_t));
    }
    for (Py_ssize_t i = 0; i < valuation_count; i++) {
        char *code;
        Py_ssize_t size;
        if (PyBytes_AsStringAndSize(PyList_GET_ITEM(valuations, i), &code, &size) < 0)
            return NULL;
        self->valuations[i].code = PyMem_Malloc(size + sizeof(int32_t));
        if (self->valuations[i].code == NULL)
            return PyErr_NoMemory();
        memcpy(self->valuations[i].code, code, size);
        self->valuations[i].code_length = size / sizeof(int32_t);
    }
    Py_RETURN_NONE;
}

/* ``step(id) -> list of state parts or None``: the step machine's successors of a stored
 * state as (frame id, data id) pairs, None where Python must step it (for tests) */
static PyObject *PackedTable_step(PackedTable *self, PyObject *argument)
{
    Py_ssize_t id = PyLong_AsSsize_t(argument);
    if (id == -1 && PyErr_Occurred())
        return NULL;
    if (id < 0 || id >= self->states.count)
        return PyErr_Format(PyExc_IndexError, "no such state id");
    if (ensure_index(self) < 0)
        return NULL;
    Scratch scratch = {0};
    Successors found = {0};
    PyObject *result = NULL;
    if (scratch_init(&scratch, self) == 0) {
        int outcome = machine_successors(self, id, &scratch, &found);
        if (outcome == VM_UNSUPPORTED)
            result = Py_NewRef(Py_None);
        else if (outcome == VM_DONE && (result = PyList_New(found.count)) != NULL)
            for (Py_ssize_t i = 0; i < found.count; i++)
                PyList_SET_ITEM(result, i, Py_BuildValue("(ii)", found.frames[i],
                                                         found.data[i]));
    }
    scratch_free(&scratch);
    PyMem_Free(found.frames);
    PyMem_Free(found.data);
    return result;
}

static PyTypeObject PackedTableType;

int packed_check(PyObject *object)
{
    return PyObject_TypeCheck(object, &PackedTableType);
}

int packed_successor_ids(PyObject *object, Py_ssize_t id, Py_ssize_t valuation,
                         Int32Vector *ids, Uint64Vector *bits, Int32Vector *valued)
{
    PackedTable *self = (PackedTable *)object;
    ids->length = bits->length = valued->length = 0;
    if (id < 0 || id >= self->states.count || valuation >= self->valuation_count) {
        PyErr_Format(PyExc_IndexError, "no such state or valuation");
        return -1;
    }
    if (ensure_index(self) < 0)
        return -1;
    if (self->scratch == NULL) {
        self->scratch = PyMem_Calloc(1, sizeof(Scratch));
        if (self->scratch == NULL) {
            PyErr_NoMemory();
            return -1;
        }
        if (scratch_init(self->scratch, self) < 0) {
            PyMem_Free(self->scratch);
            self->scratch = NULL;
            return -1;
        }
    }
    Scratch *scratch = self->scratch;
    Successors *found = &scratch->found;
    int outcome = machine_successors(self, id, scratch, found);
    self->newly_executed.length = 0;
    if (outcome < 0)
        return -1;
    if (outcome != VM_DONE) {
        self->python_steps++;
        return PACKED_UNSUPPORTED;
    }
    self->machine_steps++;
    for (Py_ssize_t i = 0; i < found->count; i++) {
        int is_new = 0;
        Py_ssize_t successor = intern_key(self, found->frames[i], found->data[i], 1, &is_new);
        if (successor < 0 || vector32_push(ids, successor) < 0)
            return -1;
        if (is_new) {
            uint64_t value = 0;
            int valued_here = valuation < 0 ? VM_UNSUPPORTED :
                machine_valuation(self, valuation, successor, scratch, &value);
            if (valued_here < 0 || vector64_push(bits, value) < 0 ||
                    vector32_push(valued, valued_here == VM_DONE) < 0)
                return -1;
        }
    }
    return PACKED_STEPPED;
}

/* ``successor_ids(id, valuation) -> (ids, bits) or None``: ``packed_successor_ids`` for
 * Python: the successors' ids in model order, and the valuation's bits of each new one in
 * id order (None where the machine did not value it; all None when the valuation is not
 * compiled, -1); None when the machine leaves the state to Python
 * (``check.store.ModelStore``'s fast path) */
static PyObject *PackedTable_successor_ids(PackedTable *self, PyObject *args)
{
    Py_ssize_t id, valuation;
    if (!PyArg_ParseTuple(args, "nn", &id, &valuation))
        return NULL;
    Int32Vector ids = {0}, valued = {0};
    Uint64Vector bits = {0};
    PyObject *id_items = NULL, *bit_items = NULL, *result = NULL;
    int outcome = packed_successor_ids((PyObject *)self, id, valuation, &ids, &bits, &valued);
    if (outcome < 0)
        goto done;
    if (outcome != PACKED_STEPPED) {
        result = Py_NewRef(Py_None);
        goto done;
    }
    id_items = int32_list(ids.items, ids.length);
    bit_items = valuation >= 0 ? PyList_New(bits.length) : Py_NewRef(Py_None);
    if (id_items == NULL || bit_items == NULL)
        goto done;
    for (Py_ssize_t i = 0; valuation >= 0 && i < bits.length; i++) {
        PyObject *item = valued.items[i] ? PyLong_FromUnsignedLongLong(bits.items[i]) :
            Py_NewRef(Py_None);              /* (None: Python values this one) */
        if (item == NULL)
            goto done;
        PyList_SET_ITEM(bit_items, i, item);
    }
    result = PyTuple_Pack(2, id_items, bit_items);
done:
    Py_XDECREF(id_items);
    Py_XDECREF(bit_items);
    vector32_free(&ids);
    vector32_free(&valued);
    vector64_free(&bits);
    return result;
}

/* ``pairs`` (a sequence of (frame id, data id), as ``python_successors`` gives them) into
 * ``found``; 0 / -1 */
static int found_from_pairs(PyObject *pairs, Successors *found)
{
    PyObject *fast = PySequence_Fast(pairs, "python_successors must give a sequence");
    if (fast == NULL)
        return -1;
    found->count = 0;
    for (Py_ssize_t i = 0; i < PySequence_Fast_GET_SIZE(fast); i++) {
        int frame, data;
        if (!PyArg_ParseTuple(PySequence_Fast_GET_ITEM(fast, i), "ii", &frame, &data) ||
                add_successor(found, frame, data) < 0) {
            Py_DECREF(fast);
            return -1;
        }
    }
    Py_DECREF(fast);
    return 0;
}

typedef struct {            /* a set of 64-bit keys, each noted once (open addressing) */
    uint64_t *slots;        /* key + 1; 0: empty */
    uint64_t mask;
    Py_ssize_t count;
} KeySet;

/* whether ``key`` is new to the set (then it is added); -1 when out of memory */
static int keyset_add(KeySet *set, uint64_t key)
{
    if (2 * (set->count + 1) > (Py_ssize_t)(set->mask + 1) || set->slots == NULL) {
        uint64_t capacity = set->slots == NULL ? 4096 : 2 * (set->mask + 1);
        uint64_t *slots = PyMem_Calloc(capacity, sizeof(uint64_t));
        if (slots == NULL) {
            PyErr_NoMemory();
            return -1;
        }
        for (uint64_t i = 0; set->slots != NULL && i <= set->mask; i++) {
            if (!set->slots[i])
                continue;
            uint64_t slot = mix64(set->slots[i] - 1) & (capacity - 1);
            while (slots[slot])
                slot = (slot + 1) & (capacity - 1);
            slots[slot] = set->slots[i];
        }
        PyMem_Free(set->slots);
        set->slots = slots;
        set->mask = capacity - 1;
    }
    uint64_t slot = mix64(key) & set->mask;
    while (set->slots[slot]) {
        if (set->slots[slot] == key + 1)
            return 0;
        slot = (slot + 1) & set->mask;
    }
    set->slots[slot] = key + 1;
    set->count++;
    return 1;
}

/* whether ``watch(id, frames, data)`` (a state's id, its successors' parts) says True;
 * asked, as the breadth-first loop's ``observe`` asks its stuck watch, only of a state the
 * machine did not step, or whose context has an ended task, or whose every successor has
 * its own call stack and data (a state where the program may be stuck); -1 on error */
static int watch_says(PackedTable *table, PyObject *watch, Py_ssize_t id, int by_machine,
                      const Successors *found)
{
    int64_t key = index_key(&table->states, id);
    int32_t frame = (int32_t)(key >> 32), data = (int32_t)(key & 0xffffffff);
    if (by_machine && !(table->context_runs[table->frames.arena[table->frames.offsets[frame]]] &
                        CONTEXT_ENDED_TASK)) {
        for (Py_ssize_t i = 0; i < found->count; i++)
            if (found->frames[i] != frame || found->data[i] != data)
                return 0;
    }
    PyObject *frames = int32_list(found->frames, found->count);
    PyObject *datas = frames == NULL ? NULL : int32_list(found->data, found->count);
    PyObject *answer = datas == NULL ? NULL :
        PyObject_CallFunction(watch, "nOO", id, frames, datas);
    Py_XDECREF(frames);
    Py_XDECREF(datas);
    if (answer == NULL)
        return -1;
    int says = PyObject_IsTrue(answer);
    Py_DECREF(answer);
    return says;
}

/* ``expand_keys(first, last, failed, watch) -> (keys, parents, transitions, deadlocks,
 * first deadlocked id or -1, first failed id or -1, whether watch said True)``: the states
 * ``first`` .. ``last`` - 1 stepped in id order (the machine's step, else
 * ``python_successors``), as a worker of a distributed search expands a round
 * (check/distributed/partition.py): their successors' keys (bytes of uint64, frame id << 32
 * | data id), each distinct one once, the first time it is reached, with the id of the
 * state it was reached from (bytes of int64).  With ``failed``, a state whose context says
 * the program failed stops the loop before it is stepped: its id is the sixth number (the
 * keys are then of the states before it).  ``watch`` (None, or as ``watch_says`` calls it)
 * is asked until it says True once. */
static PyObject *PackedTable_expand_keys(PackedTable *self, PyObject *args)
{
    Py_ssize_t first, last;
    int failed;
    PyObject *watch;
    if (!PyArg_ParseTuple(args, "nnpO", &first, &last, &failed, &watch))
        return NULL;
    int watched = 0;
    if (first < 0 || last > self->states.count || first > last)
        return PyErr_Format(PyExc_IndexError, "no such state ids");
    if (ensure_index(self) < 0)
        return NULL;
    Scratch scratch = {0};
    Successors found = {0};
    KeySet seen = {0};
    uint64_t *keys = NULL;
    int64_t *parents = NULL;
    Py_ssize_t count = 0, keys_capacity = 0, parents_capacity = 0;
    long long transitions = 0, deadlocks = 0;
    Py_ssize_t deadlocked = -1, failed_at = -1;
    PyObject *result = NULL;
    if (scratch_init(&scratch, self) < 0)
        goto done;
    for (Py_ssize_t id = first; id < last; id++) {
        if (failed) {
            int32_t frame = (int32_t)(index_key(&self->states, id) >> 32);
            if (self->context_runs[self->frames.arena[self->frames.offsets[frame]]] &
                    CONTEXT_FAILED) {
                failed_at = id;
                break;
            }
        }
        int outcome = machine_successors(self, id, &scratch, &found);
        self->newly_executed.length = 0;
        if (outcome < 0)
            goto done;
        if (outcome == VM_DONE)
            self->machine_steps++;
        else {
            self->python_steps++;
            PyObject *pairs = PyObject_CallMethod((PyObject *)self, "python_successors", "n",
                                                  id);
            int filled = pairs == NULL ? -1 : found_from_pairs(pairs, &found);
            Py_XDECREF(pairs);
            if (filled < 0)
                goto done;
        }
        if (watch != Py_None && !watched &&
                (watched = watch_says(self, watch, id, outcome == VM_DONE, &found)) < 0)
            goto done;
        transitions += found.count;
        if (found.count == 0 && deadlocks++ == 0)
            deadlocked = id;
        for (Py_ssize_t i = 0; i < found.count; i++) {
            uint64_t key = (uint64_t)(uint32_t)found.frames[i] << 32 | (uint32_t)found.data[i];
            int fresh = keyset_add(&seen, key);
            if (fresh < 0)
                goto done;
            if (!fresh)
                continue;
            uint64_t *more_keys = reserve(keys, &keys_capacity, sizeof(uint64_t), count + 1);
            if (more_keys == NULL)
                goto done;
            keys = more_keys;
            int64_t *more_parents = reserve(parents, &parents_capacity, sizeof(int64_t),
                                            count + 1);
            if (more_parents == NULL)
                goto done;
            parents = more_parents;
            keys[count] = key;
            parents[count++] = id;
        }
    }
    result = Py_BuildValue("(y#y#LLnnO)", keys != NULL ? (const char *)keys : "",
                           count * (Py_ssize_t)sizeof(uint64_t),
                           parents != NULL ? (const char *)parents : "",
                           count * (Py_ssize_t)sizeof(int64_t), transitions, deadlocks,
                           deadlocked, failed_at, watched ? Py_True : Py_False);
done:
    scratch_free(&scratch);
    PyMem_Free(found.frames);
    PyMem_Free(found.data);
    PyMem_Free(seen.slots);
    PyMem_Free(keys);
    PyMem_Free(parents);
    return result;
}

/* ``evaluate(valuation index, id) -> int or None``: compiled atoms on a stored state */
static PyObject *PackedTable_evaluate(PackedTable *self, PyObject *args)
{
    Py_ssize_t index, id;
    if (!PyArg_ParseTuple(args, "nn", &index, &id))
        return NULL;
    if (index < 0 || index >= self->valuation_count || id < 0 || id >= self->states.count)
        return PyErr_Format(PyExc_IndexError, "no such valuation or state");
    Scratch scratch = {0};
    if (scratch_init(&scratch, self) < 0)
        return NULL;
    uint64_t bits = 0;
    int outcome = machine_valuation(self, index, id, &scratch, &bits);
    scratch_free(&scratch);
    if (outcome < 0)
        return NULL;
    if (outcome == VM_UNSUPPORTED)
        Py_RETURN_NONE;
    return PyLong_FromUnsignedLongLong(bits);
}

/* ``release_index()``: drop the hash indexes (the interning is done; ids, states and the
 * machine stay; the next interning makes them again) */
static PyObject *PackedTable_release_index(PackedTable *self, PyObject *unused)
{
    PyMem_Free(self->states.slots);
    self->states.slots = NULL;
    vt_release_index(&self->frames);
    vt_release_index(&self->data);
    Py_RETURN_NONE;
}

/* ``spare_data(on)``: whether steps put the new data segments in the spare table (a
 * distributed worker's, ``data_intern``) */
static PyObject *PackedTable_spare_data(PackedTable *self, PyObject *argument)
{
    int on = PyObject_IsTrue(argument);
    if (on < 0)
        return NULL;
    self->sparing = on;
    Py_RETURN_NONE;
}

/* ``clear_spare()``: forget the spare data segments (their ids name nothing after it) */
static PyObject *PackedTable_clear_spare(PackedTable *self, PyObject *unused)
{
    if (self->spare.count == 0)
        Py_RETURN_NONE;
    vt_free(&self->spare);
    memset(&self->spare, 0, sizeof(VectorTable));
    if (vt_init(&self->spare) < 0 || (self->compact && vt_set_width(&self->spare, 1) < 0))
        return NULL;
    Py_RETURN_NONE;
}

/* ``compact()``: from now on the table keeps its states' keys in 4 bytes and its data
 * segments' items in 1 or 2 bytes while they fit (``index_key``, ``VectorTable.width``),
 * the sets of later searches too: about a third less memory a state for a few more
 * instructions a read (a distributed worker's table, check/distributed/partition.py) */
static PyObject *PackedTable_compact(PackedTable *self, PyObject *unused)
{
    self->compact = 1;
    if (index_narrow(&self->states) < 0 ||
            (self->selected != NULL && index_narrow(&self->own) < 0) ||
            vt_narrow(&self->data) < 0 || vt_narrow(&self->spare) < 0)
        return NULL;
    Py_RETURN_NONE;
}

static PyObject *PackedTable_native_bytes(PackedTable *self, PyObject *unused)
{
    Py_ssize_t bytes = self->states.key_capacity *
        (self->states.narrow ? sizeof(uint32_t) : sizeof(int64_t)) +
        (self->states.slots != NULL ? (self->states.mask + 1) * sizeof(int32_t) : 0)
        + vt_bytes(&self->frames) + vt_bytes(&self->data) + vt_bytes(&self->spare)
        + self->value_capacity * (1 + sizeof(double) + sizeof(PyObject *))
        + (self->value_mask + 1) * sizeof(int32_t)
        + vt_bytes(&self->signals) + self->context_capacity * (2 * sizeof(int32_t) + 1)
        + vt_bytes(&self->frame_questions) + vt_bytes(&self->frame_answers)
        + self->answer_of.capacity * sizeof(int32_t)
        + self->context_tasks_capacity * self->task_count * TASK_INFO * sizeof(int32_t)
        + self->places.key_capacity * sizeof(int64_t)      /* (the reduction's numbers) */
        + (self->places.slots != NULL ? (self->places.mask + 1) * sizeof(int32_t) : 0)
        + (self->row_at_capacity + self->row_capacity) * sizeof(int64_t)
        + self->big_sums_capacity * sizeof(uint64_t)
        + (self->big_slots != NULL ? (self->big_mask + 1) * (sizeof(int32_t) + sizeof(uint64_t))
           : 0);
    /* (the caches of a fixed size, ``id_cache_*`` and ``item_memo_*``, 304 KB in all, are
     * not counted: they hold no state) */
    return PyLong_FromSsize_t(bytes);
}

static PyObject *PackedTable_counts(PackedTable *self, PyObject *unused)
{
    return Py_BuildValue("{s:n,s:n,s:n,s:n,s:L,s:L,s:L,s:L,s:L,s:n,s:n,s:L}", "states",
                         self->states.count,
                         "frames", self->frames.count, "data", self->data.count,
                         "values", self->values, "machine_steps", self->machine_steps,
                         "python_steps", self->python_steps,
                         "task_machine_steps", self->task_machine_steps,
                         "task_python_steps", self->task_python_steps,
                         "rows_reused", self->rows_reused, "places", self->places.count,
                         "row_keys", self->row_length,
                         "run_frame_steps", self->run_frame_steps);
}

/* ``set_tasks(count)``: the program's tasks (2-64: each context then says where each
 * task's top frame is, ``add_context``), before the first context */
static PyObject *PackedTable_set_tasks(PackedTable *self, PyObject *argument)
{
    Py_ssize_t count = PyLong_AsSsize_t(argument);
    if (count == -1 && PyErr_Occurred())
        return NULL;
    if (count < 1 || count > 64 || self->contexts > 0)
        return PyErr_Format(PyExc_ValueError, "1-64 tasks, before the first context");
    self->task_count = count;
    Py_RETURN_NONE;
}

/* ``set_order(flags)``: the partial-order reduction of a program of several tasks
 * (model/packed/table.py's ``_order_flags``): per task, per routine, None or bytes of
 * ORDER_ flags by pc.  From then on the machine's steps of several tasks run on
 * through local instructions and keep one task's ample set (``tasks_step``). */
static PyObject *PackedTable_set_order(PackedTable *self, PyObject *flags)
{
    if (!PyList_Check(flags) || PyList_GET_SIZE(flags) != self->task_count)
        return PyErr_Format(PyExc_ValueError, "set_order: a list of one entry per task");
    Py_ssize_t routines = -1, total = 0;
    for (Py_ssize_t task = 0; task < self->task_count; task++) {
        PyObject *per_routine = PyList_GET_ITEM(flags, task);
        if (!PyList_Check(per_routine) ||
                (routines >= 0 && PyList_GET_SIZE(per_routine) != routines))
            return PyErr_Format(PyExc_ValueError, "set_order: a list per task, one per routine");
        routines = PyList_GET_SIZE(per_routine);
        for (Py_ssize_t r = 0; r < routines; r++) {
            PyObject *entry = PyList_GET_ITEM(per_routine, r);
            if (entry != Py_None && !PyBytes_Check(entry))
                return PyErr_Format(PyExc_TypeError, "set_order: bytes or None per routine");
            if (entry != Py_None)
                total += PyBytes_GET_SIZE(entry);
        }
    }
    Py_ssize_t pairs = self->task_count * (routines > 0 ? routines : 0);
    uint8_t *bytes = PyMem_Malloc(total + 1);
    int64_t *offsets = PyMem_Malloc((pairs + 1) * sizeof(int64_t));
    int64_t *lengths = PyMem_Malloc((pairs + 1) * sizeof(int64_t));
    if (bytes == NULL || offsets == NULL || lengths == NULL) {
        PyMem_Free(bytes);
        PyMem_Free(offsets);
        PyMem_Free(lengths);
        return PyErr_NoMemory();
    }
    int64_t at = 0;
    for (Py_ssize_t task = 0; task < self->task_count; task++) {
        PyObject *per_routine = PyList_GET_ITEM(flags, task);
        for (Py_ssize_t r = 0; r < routines; r++) {
            PyObject *entry = PyList_GET_ITEM(per_routine, r);
            Py_ssize_t pair = task * routines + r;
            offsets[pair] = entry == Py_None ? -1 : at;
            lengths[pair] = entry == Py_None ? 0 : PyBytes_GET_SIZE(entry);
            if (entry != Py_None) {
                memcpy(bytes + at, PyBytes_AS_STRING(entry), PyBytes_GET_SIZE(entry));
                at += PyBytes_GET_SIZE(entry);
            }
        }
    }
    PyMem_Free(self->order_flags);
    PyMem_Free(self->order_offsets);
    PyMem_Free(self->order_lengths);
    self->order_flags = bytes;
    self->order_offsets = offsets;
    self->order_lengths = lengths;
    self->order_routines = routines > 0 ? routines : 0;
    self->reduced = 1;
    Py_RETURN_NONE;
}

/* ============================================================ a check's searches */

static void StateSet_dealloc(StateSet *self)
{
    index_free(&self->index);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyTypeObject StateSetType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rapidmc.check._native.StateSet",
    .tp_doc = "The states one search of a check stored in a shared PackedTable (new_states).",
    .tp_basicsize = sizeof(StateSet),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_dealloc = (destructor)StateSet_dealloc,
};

/* Make ``chosen`` (a StateSet, or NULL: the table's own) the set whose states ids name:
 * the index in the table's fields goes back to the set it belongs to, and ``chosen``'s
 * comes in (the table holds the selected set, so it lives while its index is here). */
static void select_states(PackedTable *self, PyObject *chosen)
{
    if (chosen == self->selected)
        return;
    StateIndex *from = self->selected != NULL ? &((StateSet *)self->selected)->index :
        &self->own;
    *from = self->states;
    self->states = chosen != NULL ? ((StateSet *)chosen)->index : self->own;
    Py_XINCREF(chosen);
    Py_XSETREF(self->selected, chosen);
    self->labels_wanted = 0;            /* (the search that wanted lines is not this one) */
}

/* ``new_states() -> StateSet``: an empty set of states for a new search of the check
 * (``select`` it); the lines the machine ran are forgotten (the new search's observer
 * hears them again) */
static PyObject *PackedTable_new_states(PackedTable *self, PyObject *unused)
{
    StateSet *set = PyObject_New(StateSet, &StateSetType);
    if (set == NULL)
        return NULL;
    if (index_init(&set->index) < 0) {
        set->index.keys = NULL;
        Py_DECREF(set);
        return PyErr_NoMemory();
    }
    set->index.narrow = self->compact;
    for (Py_ssize_t r = 0; r < self->routine_count; r++)
        if (self->routines[r].executed != NULL)
            memset(self->routines[r].executed, 0, self->routines[r].length + 1);
    self->newly_executed.length = 0;
    return (PyObject *)set;
}

/* ``select(states)``: ids name the states of ``states`` (a StateSet of this table's
 * ``new_states``, or None: the table's own) from now on */
static PyObject *PackedTable_select(PackedTable *self, PyObject *chosen)
{
    if (chosen != Py_None && !PyObject_TypeCheck(chosen, &StateSetType))
        return PyErr_Format(PyExc_TypeError, "select: a StateSet or None");
    select_states(self, chosen == Py_None ? NULL : chosen);
    Py_RETURN_NONE;
}

/* ``place(frame id, data id, number) -> int``: the reduction's number of the state with
 * these segments (``PartialOrder``'s C3), given now when it has none and ``number``; -1:
 * none */
static PyObject *PackedTable_place(PackedTable *self, PyObject *args)
{
    int frame_id, data_id, number;
    if (!PyArg_ParseTuple(args, "iip", &frame_id, &data_id, &number))
        return NULL;
    Py_ssize_t place = place_of(self, frame_id, data_id, number);
    return place == -2 ? NULL : PyLong_FromSsize_t(place);
}

static Py_ssize_t PackedTable_length(PackedTable *self)
{
    return self->states.count;
}

static PyMethodDef PackedTable_methods[] = {
    {"new_states", (PyCFunction)PackedTable_new_states, METH_NOARGS,
     "new_states() -> StateSet: the states of a new search of the check (select it)"},
    {"select", (PyCFunction)PackedTable_select, METH_O,
     "select(states): ids name the states of this StateSet (None: the table's own)"},
    {"place", (PyCFunction)PackedTable_place, METH_VARARGS,
     "place(frame id, data id, number) -> int: the reduction's number of the state"},
    {"set_order", (PyCFunction)PackedTable_set_order, METH_O,
     "set_order(flags): the partial-order reduction's flags per task, routine and pc"},
    {"value_ids", (PyCFunction)PackedTable_value_ids, METH_O,
     "value_ids(values) -> bytes: the 32-bit ids of the values (stored when new)"},
    {"values", (PyCFunction)PackedTable_values, METH_O,
     "values(ids: bytes) -> tuple: the values of 32-bit ids"},
    {"add_context", (PyCFunction)PackedTable_add_context, METH_VARARGS,
     "add_context(routine, flags, signals, tasks=None) -> id: a new context id"},
    {"intern_vectors", (PyCFunction)PackedTable_intern_vectors, METH_VARARGS,
     "intern_vectors(frame, data, add=True) -> (id, new): a state by its two vectors"},
    {"vectors", (PyCFunction)PackedTable_vectors, METH_O,
     "vectors(id) -> (context, pc, locals, data): a stored state's parts"},
    {"key", (PyCFunction)PackedTable_key, METH_O,
     "key(id) -> (frame id, data id, context id): a stored state's segments and context"},
    {"parts", (PyCFunction)PackedTable_parts, METH_VARARGS,
     "parts(frame id, data id) -> (context, pc, locals, data): segments' contents"},
    {"intern_parts", (PyCFunction)PackedTable_intern_parts, METH_VARARGS,
     "intern_parts(frame, data) -> (frame id, data id): segments by their vectors"},
    {"segments", (PyCFunction)PackedTable_segments, METH_VARARGS,
     "segments(frame id, data id) -> (frame, data): interned segments' vectors as bytes"},
    {"segments_batch", (PyCFunction)PackedTable_segments_batch, METH_VARARGS,
     "segments_batch(keys) -> (frames, data, lengths): segments of many states"},
    {"owners", (PyCFunction)PackedTable_owners, METH_VARARGS,
     "owners(keys, value_prints, context_prints, count, by_data) -> bytes of uint32: the "
     "owner of each key's state in a distributed search"},
    {"intern_keys", (PyCFunction)PackedTable_intern_keys, METH_VARARGS,
     "intern_keys(keys) -> (ids, new): the states of these segment keys, stored"},
    {"intern_batch", (PyCFunction)PackedTable_intern_batch, METH_VARARGS,
     "intern_batch(frames, data, lengths) -> (ids, new): many states by their vectors"},
    {"set_program", (PyCFunction)PackedTable_set_program, METH_VARARGS,
     "set_program(store_length, io_length, routines, lazy, valuations): the compiled code"},
    {"step", (PyCFunction)PackedTable_step, METH_O,
     "step(id) -> [(frame id, data id)] or None: the step machine on a stored state"},
    {"expand_keys", (PyCFunction)PackedTable_expand_keys, METH_VARARGS,
     "expand_keys(first, last, failed, watch) -> (keys, parents, transitions, deadlocks, "
     "first deadlocked id or -1, first failed id or -1, watched): a distributed worker's "
     "round"},
    {"successor_ids", (PyCFunction)PackedTable_successor_ids, METH_VARARGS,
     "successor_ids(id, valuation) -> (ids, bits of the new ones) or None: the machine's "
     "step with the successors interned"},
    {"evaluate", (PyCFunction)PackedTable_evaluate, METH_VARARGS,
     "evaluate(valuation, id) -> bits or None: compiled atoms on a stored state"},
    {"release_index", (PyCFunction)PackedTable_release_index, METH_NOARGS,
     "release_index(): drop the hash indexes until the next interning needs them"},
    {"spare_data", (PyCFunction)PackedTable_spare_data, METH_O,
     "spare_data(on): a step's new data segments go to a spare table (distributed workers)"},
    {"clear_spare", (PyCFunction)PackedTable_clear_spare, METH_NOARGS,
     "clear_spare(): forget the spare data segments"},
    {"native_bytes", (PyCFunction)PackedTable_native_bytes, METH_NOARGS,
     "native_bytes() -> int: bytes of the native arrays"},
    {"set_tasks", (PyCFunction)PackedTable_set_tasks, METH_O,
     "set_tasks(count): the program's tasks (several: contexts say where each one's frame is)"},
    {"compact", (PyCFunction)PackedTable_compact, METH_NOARGS,
     "compact(): narrow state keys and data segments from now on (a distributed worker's)"},
    {"counts", (PyCFunction)PackedTable_counts, METH_NOARGS,
     "counts() -> dict: states, segments, values and steps taken by each engine"},
    {NULL}
};

static PySequenceMethods PackedTable_sequence = {
    .sq_length = (lenfunc)PackedTable_length,
};

static PyTypeObject PackedTableType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rapidmc.check._native.PackedTable",
    .tp_doc = "States as interned vectors of value ids, and the step machine (see _packed.c).",
    .tp_basicsize = sizeof(PackedTable),
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_BASETYPE | Py_TPFLAGS_HAVE_GC,
    .tp_new = PackedTable_new,
    .tp_traverse = (traverseproc)PackedTable_traverse,
    .tp_clear = (inquiry)PackedTable_clear,
    .tp_dealloc = (destructor)PackedTable_dealloc,
    .tp_methods = PackedTable_methods,
    .tp_as_sequence = &PackedTable_sequence,
};

/* ================================================================ breadth first */

#define FLUSH_EVERY 65536

typedef struct {                 /* one run of the packed breadth-first loop */
    PackedTable *table;
    PyObject *step_python;       /* table.python_successors(id) -> list of (frame, data) */
    PyObject *python_observe;    /* table.observe(id, successor ids) or None */
    PyObject *predicate_python;  /* table.predicate_holds(successor index) ... see below */
    PyObject *budget, *sink;
    int observe_natively;        /* stuck check and triggers here; Python for candidates */
    Py_ssize_t trigger_valuation;   /* -1: none */
    /* the predicate: 0 Python's (``predicate_holds``), PREDICATE_FAILED the program failed
     * (the context says), PREDICATE_STUCK several tasks' ``RapidSystem.stuck`` (the
     * machine's step says, as ``PackedStateTable._stuck``; else Python) */
    int predicate_is_failed;
    int deadlock_is_target, recording;
    int labels_wanted;           /* the observer still wants the lines steps run */
    Py_ssize_t *valuations;      /* per recorded valuation: its compiled index or -1 */
    Py_ssize_t valuation_count;
    long depth_now, deepest;
    Py_ssize_t level_end;
    int64_t max_states, next_checkpoint;
    long long transitions, deadlocks;
    /* buffered output, handed to ``sink`` */
    Int32Vector parents, starts, targets, unique;
    uint8_t *deadlocked;
    Py_ssize_t deadlocked_length, deadlocked_capacity;
    uint64_t *values;            /* rows of valuation_count values (interleaved) */
    Py_ssize_t values_length, values_capacity;     /* in rows */
    int64_t targets_before;      /* the graph's targets before this loop */
    /* trigger bits seen (a small set) */
    uint64_t *triggers;
    Py_ssize_t trigger_count, trigger_capacity;
    Scratch scratch;
    Successors found;
    Scratch stuck;               /* (``machine_stuck``'s step of a new state) */
} PackedSearch;

enum { PREDICATE_FAILED = 1, PREDICATE_STUCK = 2 };

/* ``PackedStateTable._stuck`` here: whether new state ``id`` of several tasks is stuck,
 * every successor of the machine's step (its own steps and Python's of single tasks)
 * being the state itself: 1, 0, VM_UNSUPPORTED (Python decides: the machine does not step
 * there, a task has ended, or the observer wants the lines steps run), -1 */
static int machine_stuck(PackedSearch *search, Py_ssize_t id)
{
    PackedTable *table = search->table;
    if (search->labels_wanted || table->labels_wanted || table->task_count < 2)
        return VM_UNSUPPORTED;
    Stored at;
    stored_state(table, id, &at);
    if (table->context_runs[at.frame[0]] & CONTEXT_ENDED_TASK)
        return VM_UNSUPPORTED;
    int32_t frame_id = at.frame_id, data_id = at.data_id;
    Successors *found = &search->stuck.found;
    int outcome = machine_successors(table, id, &search->stuck, found);
    if (outcome != VM_DONE)
        return outcome;
    for (Py_ssize_t i = 0; i < found->count; i++)
        if (found->frames[i] != frame_id || found->data[i] != data_id)
            return 0;
    return 1;
}

static int flush(PackedSearch *search)
{
#define BYTES(p) ((p) != NULL ? (const char *)(p) : "")
    PyObject *answer = PyObject_CallFunction(
        search->sink, "y#y#y#y#y#",
        BYTES(search->parents.items), search->parents.length * (Py_ssize_t)sizeof(int32_t),
        BYTES(search->starts.items), search->starts.length * (Py_ssize_t)sizeof(int32_t),
        BYTES(search->targets.items), search->targets.length * (Py_ssize_t)sizeof(int32_t),
        BYTES(search->deadlocked), search->deadlocked_length, BYTES(search->values),
        search->values_length * search->valuation_count * (Py_ssize_t)sizeof(uint64_t));
#undef BYTES
    if (answer == NULL)
        return -1;
    Py_DECREF(answer);
    search->targets_before += search->targets.length;
    search->parents.length = search->starts.length = search->targets.length = 0;
    search->deadlocked_length = search->values_length = 0;
    return 0;
}

static int note_trigger(PackedSearch *search, uint64_t bits)
{
    for (Py_ssize_t i = 0; i < search->trigger_count; i++)
        if (search->triggers[i] == bits)
            return 0;
    uint64_t *triggers = reserve(search->triggers, &search->trigger_capacity, sizeof(uint64_t),
                                 search->trigger_count + 1);
    if (triggers == NULL)
        return -1;
    search->triggers = triggers;
    search->triggers[search->trigger_count++] = bits;
    return 0;
}

/* the successors of ``frontier`` from Python (``step_python``, or with labels for the
 * observer ``python_labelled``, which also says whether it wants more): into ``found``;
 * 0 / -1 */
static int python_successors(PackedSearch *search, Py_ssize_t frontier)
{
    PyObject *pairs;
    if (search->labels_wanted) {
        PyObject *answer = PyObject_CallMethod((PyObject *)search->table, "python_labelled",
                                               "n", frontier);
        if (answer == NULL)
            return -1;
        if (!PyTuple_Check(answer) || PyTuple_GET_SIZE(answer) != 2) {
            Py_DECREF(answer);
            PyErr_SetString(PyExc_TypeError, "python_labelled must give (parts, wanted)");
            return -1;
        }
        pairs = Py_NewRef(PyTuple_GET_ITEM(answer, 0));
        search->labels_wanted = PyObject_IsTrue(PyTuple_GET_ITEM(answer, 1));
        Py_DECREF(answer);
        if (search->labels_wanted < 0) {
            Py_DECREF(pairs);
            return -1;
        }
    }
    else
        pairs = PyObject_CallFunction(search->step_python, "n", frontier);
    if (pairs == NULL)
        return -1;
    int filled = found_from_pairs(pairs, &search->found);
    Py_DECREF(pairs);
    if (filled < 0)
        return filled;
    /* (Python's row of a reduced step, kept for the later searches as the machine's are) */
    Py_ssize_t place = row_place(search->table, frontier);
    if (place == -2 || (place >= 0 && row_keep(search->table, place, &search->found) < 0))
        return -1;
    return filled;
}

enum { GO_ON = 0, FOUND = 1, STOPPED = 2, FAILED = -1 };

/* store successor ``i`` of ``frontier``; as _native.c's ``visit_successor`` */
static int visit(PackedSearch *search, Py_ssize_t frontier, Py_ssize_t i, Py_ssize_t *id)
{
    PackedTable *table = search->table;
    Py_ssize_t stored = table->states.count;
    int is_new = 0;
    *id = intern_key(table, search->found.frames[i], search->found.data[i],
                     stored < search->max_states, &is_new);
    if (*id == -2)
        return FAILED;
    if (!is_new)
        return GO_ON;
    if (*id < 0) {
        PyObject *answer = PyObject_CallMethod(search->budget, "may_store", "(n)", stored);
        Py_XDECREF(answer);
        return answer == NULL ? FAILED : STOPPED;
    }
    search->deepest = search->depth_now + 1;
    if (vector32_push(&search->parents, frontier) < 0)
        return FAILED;
    int stopped = 0;
    if (*id >= search->next_checkpoint) {
        PyObject *answer = PyObject_CallMethod(search->budget, "checkpoint", "(nLi)", *id,
                                               search->transitions, (int)search->deepest);
        if (answer == NULL)
            return FAILED;
        Py_DECREF(answer);
        search->next_checkpoint = integer_attribute(search->budget, "next_checkpoint");
        if (search->next_checkpoint < 0 || (stopped = budget_stopped(search->budget)) < 0)
            return FAILED;
    }
    /* the run-time error predicate (the program failed) is the context's to say */
    int stuck = search->predicate_is_failed == PREDICATE_STUCK ? machine_stuck(search, *id) :
        VM_UNSUPPORTED;
    if (stuck < 0)
        return FAILED;
    if (search->predicate_is_failed == PREDICATE_FAILED) {
        uint32_t context = table->frames.arena[table->frames.offsets[search->found.frames[i]]];
        if (table->context_runs[context] & CONTEXT_FAILED)
            return FOUND;
    }
    else if (stuck != VM_UNSUPPORTED) {
        if (stuck)
            return FOUND;
    }
    else {
        PyObject *answer = PyObject_CallMethod((PyObject *)table, "predicate_holds", "n", *id);
        if (answer == NULL)
            return FAILED;
        int bad = PyObject_IsTrue(answer);
        Py_DECREF(answer);
        if (bad)
            return bad < 0 ? FAILED : FOUND;
    }
    return stopped ? STOPPED : GO_ON;
}

static int record_row(PackedSearch *search, Py_ssize_t frontier, const int32_t *ids,
                      Py_ssize_t count)
{
    uint8_t *deadlocked = reserve(search->deadlocked, &search->deadlocked_capacity, 1,
                                  search->deadlocked_length + 1);
    if (deadlocked == NULL)
        return -1;
    search->deadlocked = deadlocked;
    if (count == 0) {
        if (vector32_push(&search->targets, frontier) < 0)
            return -1;
        search->deadlocked[search->deadlocked_length++] = 1;
    }
    else {
        for (Py_ssize_t i = 0; i < count; i++) {    /* distinct, in order */
            int seen = 0;
            for (Py_ssize_t j = 0; j < i && !seen; j++)
                seen = ids[j] == ids[i];
            if (!seen && vector32_push(&search->targets, ids[i]) < 0)
                return -1;
        }
        search->deadlocked[search->deadlocked_length++] = 0;
    }
    if (vector32_push(&search->starts, search->targets_before + search->targets.length) < 0)
        return -1;
    if (search->valuation_count) {
        uint64_t *rows = reserve(search->values, &search->values_capacity,
                                 search->valuation_count * sizeof(uint64_t),
                                 search->values_length + 1);
        if (rows == NULL)
            return -1;
        search->values = rows;
        uint64_t *row = rows + search->values_length * search->valuation_count;
        for (Py_ssize_t v = 0; v < search->valuation_count; v++) {
            uint64_t bits = 0;
            int outcome = VM_UNSUPPORTED;
            if (search->valuations[v] >= 0)
                outcome = machine_valuation(search->table, search->valuations[v], frontier,
                                            &search->scratch, &bits);
            if (outcome < 0)
                return -1;
            if (outcome == VM_UNSUPPORTED) {
                PyObject *answer = PyObject_CallMethod((PyObject *)search->table,
                                                       "python_valuation", "nn", v, frontier);
                if (answer == NULL)
                    return -1;
                bits = PyLong_AsUnsignedLongLong(answer);
                Py_DECREF(answer);
                if (bits == (uint64_t)-1 && PyErr_Occurred())
                    return -1;
            }
            row[v] = bits;
        }
        search->values_length++;
    }
    return 0;
}

/* the observer at ``frontier``: natively (no stuck candidate) or in Python */
static int observe(PackedSearch *search, Py_ssize_t frontier, int by_machine)
{
    if (search->python_observe == Py_None)
        return 0;
    PackedTable *table = search->table;
    int64_t key = index_key(&table->states, frontier);
    int32_t frame = (int32_t)(key >> 32), data = (int32_t)(key & 0xffffffff);
    /* (a task at a barrier waiting for one that has ended is stuck whatever the others
     * do: Python's stuck check says so) */
    if (by_machine && search->observe_natively &&
            !(table->context_runs[table->frames.arena[table->frames.offsets[frame]]] &
              CONTEXT_ENDED_TASK)) {
        int candidate = 1;     /* every successor has this call stack and data */
        for (Py_ssize_t i = 0; i < search->found.count && candidate; i++)
            candidate = search->found.frames[i] == frame && search->found.data[i] == data;
        if (!candidate) {
            if (search->trigger_valuation < 0)
                return 0;
            uint64_t bits = 0;
            int outcome = machine_valuation(table, search->trigger_valuation, frontier,
                                            &search->scratch, &bits);
            if (outcome < 0)
                return -1;
            if (outcome == VM_DONE)
                return note_trigger(search, bits);
        }
    }
    PyObject *frames = int32_list(search->found.frames, search->found.count);
    PyObject *datas = frames == NULL ? NULL : int32_list(search->found.data, search->found.count);
    PyObject *answer = datas == NULL ? NULL :
        PyObject_CallFunction(search->python_observe, "nOO", frontier, frames, datas);
    Py_XDECREF(frames);
    Py_XDECREF(datas);
    if (answer == NULL)
        return -1;
    Py_DECREF(answer);
    return 0;
}

static int expand(PackedSearch *search, Py_ssize_t frontier, Py_ssize_t *target)
{
    PackedTable *table = search->table;
    int observed_labels = search->labels_wanted && search->python_observe != Py_None;
    table->labels_wanted = observed_labels;
    int outcome = machine_successors(table, frontier, &search->scratch, &search->found);
    if (observed_labels)
        search->labels_wanted = table->labels_wanted;
    table->labels_wanted = 0;           /* (other callers of the machine: no observer) */
    if (outcome < 0)
        return FAILED;
    int by_machine = outcome == VM_DONE;
    int observed = 0;          /* (python_labelled shows the observer the labels) */
    if (by_machine) {
        table->machine_steps++;
        if (table->newly_executed.length && search->labels_wanted) {
            PyObject *answer = PyObject_CallMethod(
                (PyObject *)table, "note_executed", "y#",
                (const char *)table->newly_executed.items,
                table->newly_executed.length * (Py_ssize_t)sizeof(int32_t));
            if (answer == NULL)
                return FAILED;
            search->labels_wanted = PyObject_IsTrue(answer);
            Py_DECREF(answer);
            if (search->labels_wanted < 0)
                return FAILED;
        }
    }
    else {
        table->python_steps++;
        observed = search->labels_wanted && search->python_observe != Py_None;
        if (python_successors(search, frontier) < 0)
            return FAILED;
    }
    table->newly_executed.length = 0;
    if (!observed && observe(search, frontier, by_machine) < 0)
        return FAILED;
    Py_ssize_t count = search->found.count;
    search->transitions += count;
    if (count == 0) {
        search->deadlocks++;
        if (search->deadlock_is_target) {
            *target = frontier;
            return FOUND;
        }
    }
    Int32Vector *ids = &search->unique;
    ids->length = 0;
    for (Py_ssize_t i = 0; i < count; i++) {
        Py_ssize_t id;
        int visited = visit(search, frontier, i, &id);
        if (visited == FOUND)
            *target = id;
        if (visited != GO_ON)
            return visited;
        if (vector32_push(ids, id) < 0)
            return FAILED;
    }
    if (search->recording && record_row(search, frontier, ids->items, ids->length) < 0)
        return FAILED;
    return GO_ON;
}

static PyObject *packed_breadth_first(PyObject *module, PyObject *args)
{
    PackedSearch search = {0};
    Py_ssize_t frontier;
    PyObject *valuations;
    int recording;
    if (!PyArg_ParseTuple(args, "O!nOOpnippOOO!LLlnLp", &PackedTableType, &search.table,
                          &frontier, &search.step_python, &search.python_observe,
                          &search.observe_natively, &search.trigger_valuation,
                          &search.predicate_is_failed, &search.deadlock_is_target, &recording,
                          &search.budget, &search.sink, &PyList_Type, &valuations,
                          &search.transitions, &search.deadlocks, &search.depth_now,
                          &search.level_end, &search.targets_before, &search.labels_wanted))
        return NULL;
    search.table->newly_executed.length = 0;
    if (ensure_index(search.table) < 0)
        return NULL;
    search.recording = recording;
    search.deepest = search.depth_now;
    Py_ssize_t target = -1;
    int outcome = FAILED;
    search.valuation_count = PyList_GET_SIZE(valuations);
    search.valuations = PyMem_Calloc(search.valuation_count + 1, sizeof(Py_ssize_t));
    if (search.valuations == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t i = 0; i < search.valuation_count; i++) {
        search.valuations[i] = PyLong_AsSsize_t(PyList_GET_ITEM(valuations, i));
        if (search.valuations[i] == -1 && PyErr_Occurred())
            goto done;
    }
    if (scratch_init(&search.scratch, search.table) < 0 ||
            scratch_init(&search.stuck, search.table) < 0)
        goto done;
    search.max_states = integer_attribute(search.budget, "max_states");
    search.next_checkpoint = integer_attribute(search.budget, "next_checkpoint");
    if (search.max_states < 0 || search.next_checkpoint < 0)
        goto done;
    if (search.level_end <= frontier)
        search.level_end = search.table->states.count;
    outcome = GO_ON;
    while (outcome == GO_ON && frontier < search.table->states.count) {
        if (frontier == search.level_end) {
            search.depth_now++;
            search.level_end = search.table->states.count;
        }
        outcome = expand(&search, frontier, &target);
        if (outcome == GO_ON) {
            frontier++;
            if (search.parents.length >= FLUSH_EVERY || search.starts.length >= FLUSH_EVERY) {
                if (flush(&search) < 0)
                    outcome = FAILED;
            }
        }
    }
    if (outcome != FAILED && flush(&search) < 0)
        outcome = FAILED;
done:
    PyMem_Free(search.valuations);
    PyMem_Free(search.values);
    vector32_free(&search.parents);
    vector32_free(&search.starts);
    vector32_free(&search.targets);
    vector32_free(&search.unique);
    PyMem_Free(search.deadlocked);
    PyMem_Free(search.found.frames);
    PyMem_Free(search.found.data);
    scratch_free(&search.scratch);
    scratch_free(&search.stuck);
    if (outcome == FAILED) {
        PyMem_Free(search.triggers);
        if (search.budget != NULL)
            keep_counts(search.budget, search.transitions, search.deadlocks, search.deepest);
        return NULL;
    }
    PyObject *triggers = PyList_New(search.trigger_count);
    for (Py_ssize_t i = 0; triggers != NULL && i < search.trigger_count; i++) {
        PyObject *bits = PyLong_FromUnsignedLongLong(search.triggers[i]);
        if (bits == NULL)
            Py_CLEAR(triggers);
        else
            PyList_SET_ITEM(triggers, i, bits);
    }
    PyMem_Free(search.triggers);
    if (triggers == NULL)
        return NULL;
    return Py_BuildValue("(nLLlN)", outcome == FOUND ? target : -1, search.transitions,
                         search.deadlocks, search.deepest, triggers);
}

PyMethodDef packed_functions[] = {
    {"packed_breadth_first", packed_breadth_first, METH_VARARGS,
     "packed_breadth_first(table, frontier, python_successors, python_observe, "
     "observe_natively, trigger_valuation, predicate_is_failed, deadlock_is_target, "
     "recording, budget, sink, valuations, transitions, deadlocks, depth, level_end, "
     "targets_before, labels_wanted) -> (target id or -1, transitions, deadlocks, depth of "
     "the last stored state, trigger bits seen): reachability's loop over a PackedTable "
     "(see _packed.c)"},
    {NULL}
};

int packed_register(PyObject *module)
{
    if (PyType_Ready(&PackedTableType) < 0 || PyType_Ready(&StateSetType) < 0)
        return -1;
    Py_INCREF(&StateSetType);
    if (PyModule_AddObject(module, "StateSet", (PyObject *)&StateSetType) < 0)
        return -1;
    Py_INCREF(&PackedTableType);
    if (PyModule_AddObject(module, "PackedTable", (PyObject *)&PackedTableType) < 0)
        return -1;
    return PyModule_AddFunctions(module, packed_functions);
}
