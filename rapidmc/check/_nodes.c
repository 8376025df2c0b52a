/* Tree compression in C: nodes.py's ``NodeTable`` (the Python engine's reference).
 *
 * A value is a tree: a tuple (or a tuple subclass: a frame, a record kept as a named
 * tuple) or a persistent vector is a node keyed by its kind and the ids of its
 * children; anything else is a leaf, keyed by its type and value (one dict per type,
 * which compares as nodes.py's ``(type, value)`` keys do).  Each distinct node is stored
 * once, as a canonical object built from its children's canonical objects, so two
 * values get the same id exactly when their trees are equal.
 *
 * A canonical object is found by its address (an open-addressing table: it lives as
 * long as the table, so its address is no other object's); an equal object met again
 * is remembered by address too, in a bounded alias table that holds it alive.  A step
 * that writes one element of a 512-element array builds a tuple whose other elements
 * are canonical: interning it costs 511 address look-ups and one new node, never a deep
 * hash.  The bytes of the nodes are counted as they are added.
 */
#include "_common.h"

#define ALIAS_LIMIT (1 << 14)          /* equal non-canonical objects known, at most */
#define SMALL_CHILDREN 32

typedef struct {        /* object address -> a number (a node id, a hash), open addressing */
    PyObject **objects;
    int64_t *ids;
    uint64_t mask;
    Py_ssize_t count;
} AddressIndex;

typedef struct {
    PyObject_HEAD
    PyObject *canonical;            /* list: node id -> canonical object */
    PyObject *leaves;               /* dict: type -> dict(value -> node id) */
    PyObject *pvector;              /* pyrsistent.pvector, and the type of its vectors */
    PyTypeObject *pvector_type;
    PyObject *new_tuple;            /* tuple.__new__, for tuple subclasses */
    PyObject *getsizeof;            /* sys.getsizeof: the bytes of new objects */
    AddressIndex known;             /* canonical objects by address */
    AddressIndex aliases;           /* equal non-canonical objects (strong references) */
    /* container nodes by key: kind and children ids */
    PyTypeObject **kinds;           /* by node id; NULL for a leaf */
    int64_t *offsets;               /* by node id: its children in ``arena`` */
    int32_t *lengths;
    uint64_t *hashes;
    Py_ssize_t nodes, node_capacity;
    int32_t *arena;
    Py_ssize_t arena_length, arena_capacity;
    int32_t *key_slots;
    uint64_t key_mask;
    Py_ssize_t containers;
    Py_ssize_t bytes;               /* the nodes' objects, counted as added */
} NodeTable;

static inline uint64_t address_key(const void *pointer)
{
    return mix64((uint64_t)(uintptr_t)pointer);
}

static uint64_t children_hash(PyTypeObject *kind, const int32_t *children, Py_ssize_t length)
{
    uint64_t h = address_key(kind) ^ (uint64_t)length;
    for (Py_ssize_t i = 0; i < length; i++)
        h = mix64(h ^ ((uint64_t)(uint32_t)children[i] + 0x9e3779b97f4a7c15ULL));
    return h;
}

/* whether an object is there (found by its address), and its number in ``*number`` */
static inline int address_lookup(const AddressIndex *index, PyObject *object, int64_t *number)
{
    uint64_t position = address_key(object) & index->mask;
    for (;;) {
        PyObject *found = index->objects[position];
        if (found == NULL)
            return 0;
        if (found == object) {
            *number = index->ids[position];
            return 1;
        }
        position = (position + 1) & index->mask;
    }
}

/* the node id of an object found by its address, -1 when it is not there */
static inline int32_t address_find(const AddressIndex *index, PyObject *object)
{
    int64_t id;
    return address_lookup(index, object, &id) ? (int32_t)id : -1;
}

static int address_init(AddressIndex *index)
{
    index->mask = FIRST_CAPACITY - 1;
    index->count = 0;
    index->objects = PyMem_Calloc(FIRST_CAPACITY, sizeof(PyObject *));
    index->ids = PyMem_Malloc(FIRST_CAPACITY * sizeof(int64_t));
    if (index->objects == NULL || index->ids == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    return 0;
}

/* ``object`` -> ``id`` (not there yet), the index doubled when half full; -1 with an
 * error.  The caller keeps the object alive while it is in the index. */
static int address_put(AddressIndex *index, PyObject *object, int64_t id)
{
    if ((uint64_t)(index->count + 1) * 2 > index->mask + 1) {
        uint64_t capacity = (index->mask + 1) * 2;
        PyObject **objects = PyMem_Calloc(capacity, sizeof(PyObject *));
        int64_t *ids = PyMem_Malloc(capacity * sizeof(int64_t));
        if (objects == NULL || ids == NULL) {
            PyMem_Free(objects);
            PyMem_Free(ids);
            PyErr_NoMemory();
            return -1;
        }
        for (uint64_t i = 0; i <= index->mask; i++) {
            if (index->objects[i] == NULL)
                continue;
            uint64_t position = address_key(index->objects[i]) & (capacity - 1);
            while (objects[position] != NULL)
                position = (position + 1) & (capacity - 1);
            objects[position] = index->objects[i];
            ids[position] = index->ids[i];
        }
        PyMem_Free(index->objects);
        PyMem_Free(index->ids);
        index->objects = objects;
        index->ids = ids;
        index->mask = capacity - 1;
    }
    uint64_t position = address_key(object) & index->mask;
    while (index->objects[position] != NULL)
        position = (position + 1) & index->mask;
    index->objects[position] = object;
    index->ids[position] = id;
    index->count++;
    return 0;
}

static void address_free(AddressIndex *index)
{
    PyMem_Free(index->objects);
    PyMem_Free(index->ids);
    index->objects = NULL;
    index->ids = NULL;
}

/* an index that holds its objects forgets them all at once when full */
static void address_clear(AddressIndex *index)
{
    for (uint64_t i = 0; i <= index->mask; i++)
        Py_CLEAR(index->objects[i]);
    index->count = 0;
}

/* ``address_put`` holding ``object``, the index forgotten first when it has ``limit``
 * objects; -1 with an error */
static int address_hold(AddressIndex *index, PyObject *object, int64_t number,
                        Py_ssize_t limit)
{
    if (index->count >= limit)
        address_clear(index);
    if (address_put(index, object, number) < 0)
        return -1;
    Py_INCREF(object);
    return 0;
}

static Py_ssize_t address_bytes(const AddressIndex *index)
{
    return (Py_ssize_t)(index->mask + 1) * (sizeof(PyObject *) + sizeof(int64_t));
}

static int address_visit(AddressIndex *index, visitproc visit, void *arg)
{
    if (index->objects != NULL)
        for (uint64_t i = 0; i <= index->mask; i++)
            Py_VISIT(index->objects[i]);
    return 0;
}

/* know ``object`` (equal to node ``id``'s canonical object, not it) by its address;
 * -1 with an error */
static int add_alias(NodeTable *self, PyObject *object, int32_t id)
{
    return address_hold(&self->aliases, object, id, ALIAS_LIMIT);
}

/* the bytes of a new node's own object (objects Python keeps once cost nothing here) */
static Py_ssize_t own_bytes(NodeTable *self, PyObject *made, Py_ssize_t children, int leaf)
{
    if (leaf) {
        if (made == Py_None || PyBool_Check(made))
            return 0;
        if (PyLong_CheckExact(made)) {
            int overflow = 0;
            long value = PyLong_AsLongAndOverflow(made, &overflow);
            if (!overflow && value >= -5 && value <= 256)
                return 0;
            PyErr_Clear();
        }
    }
    PyObject *size = PyObject_CallOneArg(self->getsizeof, made);
    if (size == NULL)
        return -1;
    Py_ssize_t bytes = PyLong_AsSsize_t(size);
    Py_DECREF(size);
    if (Py_TYPE(made) == self->pvector_type)
        bytes += 8 * children;          /* the vector's node slots */
    return bytes;
}

/* a new node with canonical object ``made`` (a reference taken over); -1 with an error */
static int32_t add_node(NodeTable *self, PyObject *made, PyTypeObject *kind,
                        const int32_t *children, Py_ssize_t length, uint64_t hash)
{
    Py_ssize_t capacity = self->node_capacity;
    PyTypeObject **kinds = reserve(self->kinds, &capacity, sizeof(PyTypeObject *),
                                   self->nodes + 1);
    if (kinds == NULL)
        goto failed;
    self->kinds = kinds;
    capacity = self->node_capacity;
    int64_t *offsets = reserve(self->offsets, &capacity, sizeof(int64_t), self->nodes + 1);
    if (offsets == NULL)
        goto failed;
    self->offsets = offsets;
    capacity = self->node_capacity;
    int32_t *lengths = reserve(self->lengths, &capacity, sizeof(int32_t), self->nodes + 1);
    if (lengths == NULL)
        goto failed;
    self->lengths = lengths;
    capacity = self->node_capacity;
    uint64_t *hashes = reserve(self->hashes, &capacity, sizeof(uint64_t), self->nodes + 1);
    if (hashes == NULL)
        goto failed;
    self->hashes = hashes;
    self->node_capacity = capacity;
    if (kind != NULL && length > 0) {
        int32_t *arena = reserve(self->arena, &self->arena_capacity, sizeof(int32_t),
                                 self->arena_length + length);
        if (arena == NULL)
            goto failed;
        self->arena = arena;
        memcpy(arena + self->arena_length, children, length * sizeof(int32_t));
    }
    Py_ssize_t own = own_bytes(self, made, length, kind == NULL);
    if (own < 0 || PyList_Append(self->canonical, made) < 0)
        goto failed;
    int32_t id = (int32_t)self->nodes++;
    self->kinds[id] = kind;
    self->offsets[id] = self->arena_length;
    self->lengths[id] = (int32_t)length;
    self->hashes[id] = hash;
    if (kind != NULL)
        self->arena_length += length;
    self->bytes += own;
    Py_DECREF(made);                    /* the list holds it */
    if (address_put(&self->known, made, id) < 0)
        return -1;
    return id;
failed:
    Py_DECREF(made);
    return -1;
}

static int grow_keys(NodeTable *self)
{
    uint64_t capacity = (self->key_mask + 1) * 2;
    int32_t *slots = new_slots((Py_ssize_t)capacity);
    if (slots == NULL)
        return -1;
    for (Py_ssize_t id = 0; id < self->nodes; id++) {
        if (self->kinds[id] == NULL)
            continue;
        uint64_t position = self->hashes[id] & (capacity - 1);
        while (slots[position] != EMPTY)
            position = (position + 1) & (capacity - 1);
        slots[position] = (int32_t)id;
    }
    PyMem_Free(self->key_slots);
    self->key_slots = slots;
    self->key_mask = capacity - 1;
    return 0;
}

static int32_t leaf_id(NodeTable *self, PyObject *value)
{
    PyObject *kind = (PyObject *)Py_TYPE(value);
    PyObject *values = PyDict_GetItemWithError(self->leaves, kind);
    if (values == NULL) {
        if (PyErr_Occurred())
            return -1;
        values = PyDict_New();
        if (values == NULL || PyDict_SetItem(self->leaves, kind, values) < 0) {
            Py_XDECREF(values);
            return -1;
        }
        Py_DECREF(values);              /* the dict holds it */
    }
    PyObject *known = PyDict_GetItemWithError(values, value);
    if (known != NULL)
        return (int32_t)PyLong_AsLong(known);
    if (PyErr_Occurred())
        return -1;
    Py_INCREF(value);
    int32_t id = add_node(self, value, NULL, NULL, 0, 0);
    if (id < 0)
        return -1;
    PyObject *number = PyLong_FromLong(id);
    if (number == NULL || PyDict_SetItem(values, value, number) < 0) {
        Py_XDECREF(number);
        return -1;
    }
    Py_DECREF(number);
    self->bytes += 3 * 8 * 2;           /* its dict entry */
    return id;
}

static int32_t node_id(NodeTable *self, PyObject *value);

/* the canonical object of a new container node of ``kind`` with ``children`` (a new
 * reference): ``value`` itself when its items are the children's canonical objects */
static PyObject *canonical_object(NodeTable *self, PyObject *value, PyObject *items,
                                  PyTypeObject *kind, const int32_t *children,
                                  Py_ssize_t length)
{
    PyObject **item = PySequence_Fast_ITEMS(items);
    if (kind != self->pvector_type) {
        Py_ssize_t i = 0;
        while (i < length && PyList_GET_ITEM(self->canonical, children[i]) == item[i])
            i++;
        if (i == length) {
            Py_INCREF(value);
            return value;
        }
    }
    PyObject *parts = PyTuple_New(length);
    if (parts == NULL)
        return NULL;
    for (Py_ssize_t i = 0; i < length; i++) {
        PyObject *part = PyList_GET_ITEM(self->canonical, children[i]);
        Py_INCREF(part);
        PyTuple_SET_ITEM(parts, i, part);
    }
    if (kind == &PyTuple_Type)
        return parts;
    PyObject *made = kind == self->pvector_type ?
        PyObject_CallOneArg(self->pvector, parts) :
        PyObject_CallFunctionObjArgs(self->new_tuple, (PyObject *)kind, parts, NULL);
    Py_DECREF(parts);
    return made;
}

static int32_t container_id(NodeTable *self, PyObject *value, PyTypeObject *kind)
{
    PyObject *items = PySequence_Fast(value, "a node's children");
    if (items == NULL)
        return -1;
    Py_ssize_t length = PySequence_Fast_GET_SIZE(items);
    int32_t small[SMALL_CHILDREN];
    int32_t *children = length <= SMALL_CHILDREN ? small : PyMem_Malloc(length * sizeof(int32_t));
    int32_t id = -1;
    if (children == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    PyObject **item = PySequence_Fast_ITEMS(items);
    for (Py_ssize_t i = 0; i < length; i++) {
        int32_t child = address_find(&self->known, item[i]);
        if (child < 0 && (child = node_id(self, item[i])) < 0)
            goto done;
        children[i] = child;
    }
    uint64_t hash = children_hash(kind, children, length);
    uint64_t position = hash & self->key_mask;
    for (;;) {
        int32_t found = self->key_slots[position];
        if (found == EMPTY)
            break;
        if (self->hashes[found] == hash && self->kinds[found] == kind &&
            self->lengths[found] == length &&
            memcmp(self->arena + self->offsets[found], children,
                   length * sizeof(int32_t)) == 0) {
            /* an equal object met again: known by its address from now on */
            id = add_alias(self, value, found) < 0 ? -1 : found;
            goto done;
        }
        position = (position + 1) & self->key_mask;
    }
    PyObject *made = canonical_object(self, value, items, kind, children, length);
    if (made == NULL)
        goto done;
    int alias = made != value;
    id = add_node(self, made, kind, children, length, hash);
    if (id < 0)
        goto done;
    self->key_slots[position] = id;
    self->containers++;
    /* the state holding ``value`` hands it on: found by address there */
    if ((alias && add_alias(self, value, id) < 0) ||
        ((uint64_t)self->containers * 2 > self->key_mask + 1 && grow_keys(self) < 0))
        id = -1;
done:
    if (children != small)
        PyMem_Free(children);
    Py_DECREF(items);
    return id;
}

/* the id of ``value``'s tree, its nodes added when new; -1 with an error */
static int32_t node_id(NodeTable *self, PyObject *value)
{
    int32_t id = address_find(&self->known, value);
    if (id >= 0)
        return id;
    PyTypeObject *kind = Py_TYPE(value);
    if (kind != self->pvector_type && !PyTuple_Check(value))
        return leaf_id(self, value);
    id = address_find(&self->aliases, value);
    if (id >= 0)
        return id;
    return container_id(self, value, kind);
}

/* ------------------------------------------------------------------ the type */

static PyObject *NodeTable_new(PyTypeObject *type, PyObject *args, PyObject *kwargs)
{
    NodeTable *self = (NodeTable *)type->tp_alloc(type, 0);
    if (self == NULL)
        return NULL;
    PyObject *pyrsistent = PyImport_ImportModule("pyrsistent");
    PyObject *sys = PyImport_ImportModule("sys");
    if (pyrsistent == NULL || sys == NULL)
        goto failed;
    self->pvector = PyObject_GetAttrString(pyrsistent, "pvector");
    self->getsizeof = PyObject_GetAttrString(sys, "getsizeof");
    self->new_tuple = PyObject_GetAttrString((PyObject *)&PyTuple_Type, "__new__");
    self->canonical = PyList_New(0);
    self->leaves = PyDict_New();
    if (self->pvector == NULL || self->getsizeof == NULL || self->new_tuple == NULL ||
        self->canonical == NULL || self->leaves == NULL)
        goto failed;
    PyObject *empty = PyObject_CallNoArgs(self->pvector);
    if (empty == NULL)
        goto failed;
    self->pvector_type = Py_TYPE(empty);
    Py_INCREF(self->pvector_type);
    Py_DECREF(empty);
    self->key_mask = FIRST_CAPACITY - 1;
    self->key_slots = new_slots(FIRST_CAPACITY);
    if (self->key_slots == NULL || address_init(&self->known) < 0 ||
        address_init(&self->aliases) < 0)
        goto failed;
    Py_DECREF(pyrsistent);
    Py_DECREF(sys);
    return (PyObject *)self;
failed:
    Py_XDECREF(pyrsistent);
    Py_XDECREF(sys);
    Py_DECREF(self);
    return NULL;
}

static int NodeTable_traverse(NodeTable *self, visitproc visit, void *arg)
{
    Py_VISIT(self->canonical);
    Py_VISIT(self->leaves);
    Py_VISIT(self->pvector);
    Py_VISIT(self->pvector_type);
    Py_VISIT(self->new_tuple);
    Py_VISIT(self->getsizeof);
    return address_visit(&self->aliases, visit, arg);
}

static int NodeTable_clear(NodeTable *self)
{
    Py_CLEAR(self->canonical);
    Py_CLEAR(self->leaves);
    Py_CLEAR(self->pvector);
    Py_CLEAR(self->pvector_type);
    Py_CLEAR(self->new_tuple);
    Py_CLEAR(self->getsizeof);
    if (self->aliases.objects != NULL)
        address_clear(&self->aliases);
    return 0;
}

static void NodeTable_dealloc(NodeTable *self)
{
    PyObject_GC_UnTrack(self);
    NodeTable_clear(self);
    address_free(&self->known);
    address_free(&self->aliases);
    PyMem_Free(self->kinds);
    PyMem_Free(self->offsets);
    PyMem_Free(self->lengths);
    PyMem_Free(self->hashes);
    PyMem_Free(self->arena);
    PyMem_Free(self->key_slots);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyObject *NodeTable_node(NodeTable *self, PyObject *value)
{
    int32_t id = node_id(self, value);
    return id < 0 ? NULL : PyLong_FromLong(id);
}

/* the canonical object of node id ``argument`` (a new reference) */
static PyObject *NodeTable_value(NodeTable *self, PyObject *argument)
{
    Py_ssize_t id = PyLong_AsSsize_t(argument);
    if (id == -1 && PyErr_Occurred())
        return NULL;
    if (id < 0 || id >= self->nodes) {
        PyErr_SetString(PyExc_IndexError, "node id out of range");
        return NULL;
    }
    PyObject *made = PyList_GET_ITEM(self->canonical, id);
    Py_INCREF(made);
    return made;
}

/* the tuple of ``each(self, item)`` over a sequence */
static PyObject *each_of(NodeTable *self, PyObject *sequence,
                         PyObject *(*each)(NodeTable *, PyObject *))
{
    PyObject *items = PySequence_Fast(sequence, "a sequence is needed");
    if (items == NULL)
        return NULL;
    Py_ssize_t length = PySequence_Fast_GET_SIZE(items);
    PyObject *result = PyTuple_New(length);
    for (Py_ssize_t i = 0; result != NULL && i < length; i++) {
        PyObject *found = each(self, PySequence_Fast_GET_ITEM(items, i));
        if (found == NULL)
            Py_CLEAR(result);
        else
            PyTuple_SET_ITEM(result, i, found);
    }
    Py_DECREF(items);
    return result;
}

static PyObject *NodeTable_ids(NodeTable *self, PyObject *values)
{
    return each_of(self, values, NodeTable_node);
}

static PyObject *NodeTable_values(NodeTable *self, PyObject *ids)
{
    return each_of(self, ids, NodeTable_value);
}

static PyObject *NodeTable_memory_bytes(NodeTable *self, PyObject *unused)
{
    size_t bytes = (size_t)self->bytes +
        (size_t)self->node_capacity * (sizeof(PyTypeObject *) + sizeof(int64_t) +
                                       sizeof(int32_t) + sizeof(uint64_t) + sizeof(PyObject *)) +
        (size_t)self->arena_capacity * sizeof(int32_t) +
        (self->key_mask + 1) * sizeof(int32_t) +
        address_bytes(&self->known) + address_bytes(&self->aliases);
    return PyLong_FromSize_t(bytes);
}

static Py_ssize_t NodeTable_length(NodeTable *self)
{
    return self->nodes;
}

static PyMethodDef NodeTable_methods[] = {
    {"node", (PyCFunction)NodeTable_node, METH_O,
     "node(value) -> id: the id of value's tree (its nodes added when new)."},
    {"ids", (PyCFunction)NodeTable_ids, METH_O,
     "ids(values) -> tuple: the node id of each value."},
    {"value", (PyCFunction)NodeTable_value, METH_O,
     "value(id) -> the node's canonical object."},
    {"values", (PyCFunction)NodeTable_values, METH_O,
     "values(ids) -> tuple: the canonical object of each node id."},
    {"memory_bytes", (PyCFunction)NodeTable_memory_bytes, METH_NOARGS,
     "Bytes of the nodes and their indexes, counted as they were added."},
    {NULL}
};

static PySequenceMethods NodeTable_as_sequence = {
    .sq_length = (lenfunc)NodeTable_length,
};

static PyTypeObject NodeTableType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rapidmc.check._native.NodeTable",
    .tp_doc = "Values as trees of interned nodes (check/nodes.py's NodeTable, in C).",
    .tp_basicsize = sizeof(NodeTable),
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_BASETYPE | Py_TPFLAGS_HAVE_GC,
    .tp_new = NodeTable_new,
    .tp_traverse = (traverseproc)NodeTable_traverse,
    .tp_clear = (inquiry)NodeTable_clear,
    .tp_dealloc = (destructor)NodeTable_dealloc,
    .tp_methods = NodeTable_methods,
    .tp_as_sequence = &NodeTable_as_sequence,
};

/* ================================================================ PartHashes */

/* model/state_keys.py's hashes remembered by the identity of the part hashed: ``of(part)``
 * is ``hash(part)``, ``of_items(sequence)`` the hash of the tuple of its items' hashes
 * (a tuple or persistent vector item's remembered, any other hashed at once); each index
 * holds the objects it remembers (so an address is never another object's) and forgets
 * them all at once when it holds ``limit``.  The same numbers as the Python code's, so
 * a search's partial-order reduction chooses the same steps on both engines. */

typedef struct {
    PyObject_HEAD
    AddressIndex parts;             /* part -> hash(part) */
    AddressIndex sequences;         /* sequence -> hash of its items' hashes */
    PyTypeObject *pvector_type;
    Py_ssize_t limit;
} PartHashes;

static int part_hash(PartHashes *self, PyObject *value, Py_hash_t *hash)
{
    int64_t known;
    if (address_lookup(&self->parts, value, &known)) {
        *hash = (Py_hash_t)known;
        return 0;
    }
    *hash = PyObject_Hash(value);
    if (*hash == -1)
        return -1;
    return address_hold(&self->parts, value, *hash, self->limit);
}

static PyObject *PartHashes_of(PartHashes *self, PyObject *value)
{
    Py_hash_t hash;
    return part_hash(self, value, &hash) < 0 ? NULL : PyLong_FromSsize_t(hash);
}

static PyObject *PartHashes_of_items(PartHashes *self, PyObject *sequence)
{
    int64_t known;
    if (address_lookup(&self->sequences, sequence, &known))
        return PyLong_FromSsize_t((Py_ssize_t)known);
    PyObject *items = PySequence_Fast(sequence, "of_items takes a sequence");
    if (items == NULL)
        return NULL;
    Py_ssize_t length = PySequence_Fast_GET_SIZE(items);
    PyObject *hashes = PyTuple_New(length);
    for (Py_ssize_t i = 0; hashes != NULL && i < length; i++) {
        PyObject *item = PySequence_Fast_GET_ITEM(items, i);
        PyTypeObject *kind = Py_TYPE(item);
        Py_hash_t hash;
        PyObject *number = NULL;
        if (kind == &PyTuple_Type || kind == self->pvector_type ?
                part_hash(self, item, &hash) == 0 : (hash = PyObject_Hash(item)) != -1)
            number = PyLong_FromSsize_t(hash);
        if (number == NULL)
            Py_CLEAR(hashes);
        else
            PyTuple_SET_ITEM(hashes, i, number);
    }
    Py_DECREF(items);
    if (hashes == NULL)
        return NULL;
    Py_hash_t hash = PyObject_Hash(hashes);
    Py_DECREF(hashes);
    if (hash == -1 || address_hold(&self->sequences, sequence, hash, self->limit) < 0)
        return NULL;
    return PyLong_FromSsize_t(hash);
}

static PyObject *PartHashes_new(PyTypeObject *type, PyObject *args, PyObject *kwargs)
{
    Py_ssize_t limit;
    if (!PyArg_ParseTuple(args, "n:PartHashes", &limit))
        return NULL;
    PartHashes *self = (PartHashes *)type->tp_alloc(type, 0);
    if (self == NULL)
        return NULL;
    self->limit = limit;
    PyObject *pyrsistent = PyImport_ImportModule("pyrsistent");
    PyObject *empty = pyrsistent == NULL ? NULL :
        PyObject_CallMethod(pyrsistent, "pvector", NULL);
    Py_XDECREF(pyrsistent);
    if (empty == NULL || address_init(&self->parts) < 0 ||
        address_init(&self->sequences) < 0) {
        Py_XDECREF(empty);
        Py_DECREF(self);
        return NULL;
    }
    self->pvector_type = Py_TYPE(empty);
    Py_INCREF(self->pvector_type);
    Py_DECREF(empty);
    return (PyObject *)self;
}

static int PartHashes_traverse(PartHashes *self, visitproc visit, void *arg)
{
    Py_VISIT(self->pvector_type);
    if (address_visit(&self->parts, visit, arg) != 0)
        return -1;
    return address_visit(&self->sequences, visit, arg);
}

static int PartHashes_clear(PartHashes *self)
{
    Py_CLEAR(self->pvector_type);
    if (self->parts.objects != NULL)
        address_clear(&self->parts);
    if (self->sequences.objects != NULL)
        address_clear(&self->sequences);
    return 0;
}

static void PartHashes_dealloc(PartHashes *self)
{
    PyObject_GC_UnTrack(self);
    PartHashes_clear(self);
    address_free(&self->parts);
    address_free(&self->sequences);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyMethodDef PartHashes_methods[] = {
    {"of", (PyCFunction)PartHashes_of, METH_O,
     "of(part) -> hash(part), remembered by the part's identity."},
    {"of_items", (PyCFunction)PartHashes_of_items, METH_O,
     "of_items(sequence) -> the hash of its items' hashes, remembered by its identity."},
    {NULL}
};

static PyTypeObject PartHashesType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rapidmc.check._native.PartHashes",
    .tp_doc = "PartHashes(limit): hashes remembered by identity (model/state_keys.py).",
    .tp_basicsize = sizeof(PartHashes),
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC,
    .tp_new = PartHashes_new,
    .tp_traverse = (traverseproc)PartHashes_traverse,
    .tp_clear = (inquiry)PartHashes_clear,
    .tp_dealloc = (destructor)PartHashes_dealloc,
    .tp_methods = PartHashes_methods,
};

int nodes_register(PyObject *module)
{
    if (PyType_Ready(&NodeTableType) < 0 || PyType_Ready(&PartHashesType) < 0)
        return -1;
    Py_INCREF(&NodeTableType);
    if (PyModule_AddObject(module, "NodeTable", (PyObject *)&NodeTableType) < 0) {
        Py_DECREF(&NodeTableType);
        return -1;
    }
    Py_INCREF(&PartHashesType);
    if (PyModule_AddObject(module, "PartHashes", (PyObject *)&PartHashesType) < 0) {
        Py_DECREF(&PartHashesType);
        return -1;
    }
    return 0;
}
