"""Sockets: the controller's TCP/IP client and server instructions.

A socket is part of the environment.  In ``run`` mode a received message
is one line of standard input (as FlexPendant answers are) and a sent one
is printed as ``[socket] <text>``; when standard input ends, the peer has
closed the connection (ERR_SOCK_CLOSED once, then the run stops for want
of input).  When model checking, a received message is a nondeterministic
choice among the configured messages, and a finite ``\\Time`` may run out
(ERR_SOCK_TIMEOUT).  A UDP datagram (SocketReceiveFrom, on a bound socket)
comes from the same source; its sender is not modelled.  docs/semantics.md,
"Sockets and files", has the details.

A ``socketdev`` variable holds ``None`` (never created: SOCKET_CLOSED) or a
pair ``(status, pending)``: the socketstatus number and the received
bytes not read yet (``\\ReadNoOfBytes`` reads a stream, not messages).

``\\Data`` (an array of byte) sends and receives bytes as ``\\RawData`` does, one
element a byte: SocketSend sends the array's elements (the first ``\\NoOfBytes`` of
them), each a byte 0..255 (else ERR_ARGVALERR); SocketReceive stores the bytes received
from the first element on, at most as many as the array holds (1,024 at most, the
manual's limit) or ``\\ReadNoOfBytes`` exactly, and leaves the elements after them and
the bytes not read as they are (the rest of the stream stays pending).
"""
from __future__ import annotations

from typing import Optional

from ...diagnostics import INPUT_EXHAUSTED, TYPE_MISMATCH, UNSUPPORTED, error
from .. import rawbytes, values
from ..errors import RapidError
from ..expressions import Compiled
from ..instructions import Action, ChosenWrite, ConstantWrite
from ..types import NUM, ArrayType, is_numeric
from .arguments import Arguments, argument_expression
from .data import PREDEFINED_DATA
from .environment_model import configured_site_domain, site_domain, where
from .registry import CHOICE, compiled
from .signature_parts import TIME

SOCKET_CREATED, SOCKET_CONNECTED, SOCKET_BOUND, SOCKET_LISTENING, SOCKET_CLOSED = \
    1.0, 2.0, 3.0, 4.0, 5.0
DEFAULT_TIMEOUT = 60.0          # seconds, when \Time is not given (manual)
WAIT_MAX = float(PREDEFINED_DATA["WAIT_MAX"].value)
TIMEOUT, CLOSED, RECEIVED = "ERR_SOCK_TIMEOUT", "ERR_SOCK_CLOSED", "received"
ADDRESS_IN_USE = "ERR_SOCK_ADDR_INUSE"


# ===========================================================================
# The environment: where received text comes from
# ===========================================================================

def configured(m, name: str, default: tuple) -> tuple:
    """Check mode: the domain ``m.chooser.config.<name>`` (``default`` when not configured)."""
    config = getattr(m.chooser, "config", None)
    return tuple(getattr(config, name, default)) or default


def environment_text(m, kind: str, span, domain: tuple):
    """The next text the environment delivers to ``kind``, or None at end of input.

    Run mode reads one line of standard input; check mode chooses from ``domain``.
    """
    if m.chooser.check_mode:
        return m.choose(f"{kind} at {where(span)}", domain)
    stdin = getattr(m.chooser, "stdin", None)
    line = stdin.readline() if stdin is not None else ""
    if not line:
        return None
    return line.rstrip("\r\n")


def may_fail(m, kind: str, span, outcomes: tuple) -> str:
    """Check mode: which of RECEIVED and the failure ``outcomes`` happens (a choice)."""
    if not outcomes or not m.chooser.check_mode:
        return RECEIVED
    return m.choose(f"{kind} outcome at {where(span)}", (RECEIVED,) + outcomes)


def _timeouts(m, seconds) -> tuple:
    return _configured_timeouts(getattr(m.chooser, "config", None), seconds)


def _configured_timeouts(config, seconds) -> tuple:
    """ERR_SOCK_TIMEOUT is possible when the time limit is finite and timeouts are modelled."""
    limit = DEFAULT_TIMEOUT if seconds is None else seconds
    if limit < WAIT_MAX and getattr(config, "socket_timeouts", True):
        return (TIMEOUT,)
    return ()


def _closures(m) -> tuple:
    return _configured_closures(getattr(m.chooser, "config", None))


def _configured_closures(config) -> tuple:
    return (CLOSED,) if getattr(config, "socket_closures", False) else ()


def _input_ended(m, what: str, span) -> None:
    """Run mode: after the input ended, no client comes any more."""
    if not m.chooser.check_mode and getattr(m.chooser, "socket_input_ended", False):
        raise error(INPUT_EXHAUSTED, f"{what} waits for a client but standard input has no "
                    "more lines (the last client closed the connection)", span)


# ===========================================================================
# Socket states
# ===========================================================================

def status(value) -> float:
    return SOCKET_CLOSED if value is None else value[0]


def _require(value, wanted: float, what: str) -> None:
    if status(value) != wanted:
        if wanted == SOCKET_CONNECTED:
            raise RapidError("ERR_SOCK_CLOSED", f"{what}: the socket is not connected")
        raise RapidError("ERR_SOCK_CLOSED", f"{what}: the socket is in the wrong state")


def _readable_count(count, most: int, instruction: str) -> None:
    """``\\ReadNoOfBytes`` asks for 1 up to the size of the data it fills: 1,024 bytes of a
    rawbytes, 80 characters of a string.  More can never be stored, so the instruction fails
    before it waits (a count unpacked from a message's header: 10^18 bytes would otherwise
    gather messages in one step without end)."""
    if count is not None and (count != int(count) or not 1 <= count <= most):
        raise RapidError("ERR_ARGVALERR", f"{instruction}: ReadNoOfBytes {values.format_num(count)} "
                         f"is outside 1..{most}")


def _optional(value):
    from ..machine import ABSENT
    return None if value is ABSENT else value


# instruction: (state it needs, or None for any; state it leaves)
TRANSITIONS = {
    "SOCKETCREATE": (None, SOCKET_CREATED),
    "SOCKETBIND": (SOCKET_CREATED, SOCKET_BOUND),
    "SOCKETLISTEN": (SOCKET_BOUND, SOCKET_LISTENING),
    "SOCKETCLOSE": (None, SOCKET_CLOSED),
}


@compiled("SocketCreate(VAR socketdev Socket \\switch UDP)",
          "SocketBind(VAR socketdev Socket, string LocalAddress, num LocalPort)",
          "SocketListen(VAR socketdev Socket)",
          "SocketClose(VAR socketdev Socket)")
def _socket_transition(calls, compiler, call, entry):
    """Moves a socket from the state the instruction needs to the one it leaves."""
    arguments = Arguments(calls, compiler, call, entry)
    socket = arguments.fn("Socket")
    wanted, new = TRANSITIONS[call.name.key]
    name = call.name.text

    binds = call.name.key == "SOCKETBIND"
    label = f"{name} outcome at {where(call.span)}"

    def act(m):
        ref = socket(m)
        if wanted is not None:
            _require(m.read_ref(ref), wanted, name)
        if binds and _setup_failures(m) and m.choose(label, ("bound", ADDRESS_IN_USE)) \
                == ADDRESS_IN_USE:
            raise RapidError(ADDRESS_IN_USE, f"{name}: the address and port are in use")
        m.write_ref(ref, (new, b""))
    action = Action(call.span, act)
    ref = arguments.global_reference("Socket")
    if ref is not None:             # (the step machine's: a socket with no data pending)
        action.machine = ConstantWrite(ref[1], () if wanted is None else ((wanted, b""),),
                                       (new, b""), "socket_setup_failures" if binds else "")
    return action


def _constant_or_absent(arguments: Arguments, call, key: str) -> bool:
    """Whether the optional argument ``key`` is absent or a constant (its value then
    neither fails nor chooses)."""
    if argument_expression(call, key, -1) is None:
        return True
    compiled = arguments.compiled(key)
    return compiled is not None and compiled.is_constant


def _setup_failures(m) -> bool:
    """Whether a server's port may be taken (the closure probe's ``socket_setup_failures``:
    a port the previous run still holds, ERR_SOCK_ADDR_INUSE at SocketBind); never for
    verdicts."""
    return m.chooser.check_mode and \
        getattr(getattr(m.chooser, "config", None), "socket_setup_failures", False)


def _connection(m, call, seconds, failure: str) -> None:
    """A connection is made, or (check mode, finite time limit) times out."""
    what = call.name.text
    _input_ended(m, what, call.span)
    if may_fail(m, what, call.span, _timeouts(m, _optional(seconds(m)))) != RECEIVED:
        raise RapidError("ERR_SOCK_TIMEOUT", f"{what}: {failure}")


@compiled(f"SocketConnect(VAR socketdev Socket, string Address, num Port {TIME})",
          modelled=CHOICE)
def _socket_connect(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    socket, seconds = arguments.fn("Socket"), arguments.value("Time")

    def connect(m):
        ref = socket(m)
        _require(m.read_ref(ref), SOCKET_CREATED, "SocketConnect")
        _connection(m, call, seconds, "no answer from the server")
        m.write_ref(ref, (SOCKET_CONNECTED, b""))
    action = Action(call.span, connect)
    ref = arguments.global_reference("Socket")
    if ref is not None and _constant_or_absent(arguments, call, "Time"):
        action.machine = ConstantWrite(ref[1], ((SOCKET_CREATED, b""),),
                                       (SOCKET_CONNECTED, b""), "socket_timeouts")
    return action


@compiled("SocketAccept(VAR socketdev Socket, VAR socketdev ClientSocket "
              f"\\VAR string ClientAddress {TIME})",
          modelled=CHOICE)
def _socket_accept(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    server, client = arguments.fn("Socket"), arguments.fn("ClientSocket")
    address, seconds = arguments.fn("ClientAddress"), arguments.value("Time")
    has_address = argument_expression(call, "ClientAddress", -1) is not None

    def accept(m):
        _require(m.read_ref(server(m)), SOCKET_LISTENING, "SocketAccept")
        _connection(m, call, seconds, "no client connected in time")
        m.write_ref(client(m), (SOCKET_CONNECTED, b""))
        if has_address:
            m.write_ref(address(m), "127.0.0.1")
    return Action(call.span, accept)


@compiled("socketstatus SocketGetStatus(VAR socketdev Socket)")
def _socket_get_status(calls, compiler, call, entry) -> Compiled:
    socket = Arguments(calls, compiler, call, entry).fn("Socket")
    return Compiled(lambda m: status(m.read_ref(socket(m))), NUM)


@compiled("num SocketPeek(VAR socketdev Socket)")
def _socket_peek(calls, compiler, call, entry) -> Compiled:
    socket = Arguments(calls, compiler, call, entry).fn("Socket")

    def peek(m):
        value = m.read_ref(socket(m))
        _require(value, SOCKET_CONNECTED, "SocketPeek")
        return float(len(value[1]))
    return Compiled(peek, NUM)


# ===========================================================================
# Sending and receiving
# ===========================================================================

def _data_size(compiler, call) -> Optional[int]:
    """None without ``\\Data``; else the number of elements of its array of byte (0 for a
    conformant ``{*}`` parameter, known only when the call runs)."""
    expr = argument_expression(call, "Data", -1)
    if expr is None:
        return None
    rapid_type = compiler.reference(expr, "read")[1]
    if not (isinstance(rapid_type, ArrayType) and rapid_type.rank == 1
            and is_numeric(rapid_type.element)):
        raise error(TYPE_MISMATCH, f"{call.name.text} \\Data needs an array of byte, not "
                    f"{rapid_type}", expr.span)
    return rapid_type.dims[0] or 0


def _bytes_of(elements: tuple, count, instruction: str) -> bytes:
    """The bytes SocketSend \\Data sends: the array's elements, the first ``count`` of them."""
    size = len(elements) if count is None else count
    if size != int(size) or not 1 <= size <= min(len(elements), rawbytes.MAX_BYTES):
        raise RapidError("ERR_ARGVALERR", f"{instruction}: NoOfBytes {values.format_num(size)} "
                         f"is outside 1..{min(len(elements), rawbytes.MAX_BYTES)}")
    chosen = elements[:int(size)]
    for value in chosen:
        if value != int(value) or not 0 <= value <= 255:
            raise RapidError("ERR_ARGVALERR", f"{instruction}: \\Data holds "
                             f"{values.format_num(value)}, not a byte 0..255")
    return bytes(int(value) for value in chosen)


def _stored(elements: tuple, data: bytes) -> tuple:
    """The array after SocketReceive \\Data: the bytes from its first element on."""
    return tuple(float(b) for b in data) + tuple(elements[len(data):])


@compiled("SocketSend(VAR socketdev Socket \\string Str | VAR rawbytes RawData | VAR anytype Data "
              "\\num NoOfBytes)",
          modelled=CHOICE)
def _socket_send(calls, compiler, call, entry):
    has_data = _data_size(compiler, call) is not None
    arguments = Arguments(calls, compiler, call, entry)
    socket, text, raw = arguments.fn("Socket"), arguments.value("Str"), arguments.value("RawData")
    count, array = arguments.value("NoOfBytes"), arguments.value("Data")
    is_raw = argument_expression(call, "RawData", -1) is not None
    if not is_raw and not has_data and argument_expression(call, "Str", -1) is None:
        raise error(UNSUPPORTED, "SocketSend needs \\Str, \\RawData or \\Data", call.span)

    def send(m):
        _require(m.read_ref(socket(m)), SOCKET_CONNECTED, "SocketSend")
        # a peer that closed the connection makes the send fail (only when closures are tried)
        if may_fail(m, "SocketSend", call.span, _closures(m)) != RECEIVED:
            raise RapidError("ERR_SOCK_CLOSED", "SocketSend: the peer closed the connection")
        limit = _optional(count(m))
        if has_data:
            shown = rawbytes.to_text(_bytes_of(array(m), limit, "SocketSend"))
        elif is_raw:
            data = rawbytes.as_bytes(raw(m))
            shown = rawbytes.to_text(data if limit is None else data[:int(limit)])
        else:
            shown = text(m) if limit is None else text(m)[:int(limit)]
        m.output.append(f"[socket] {shown}")
    action = Action(call.span, send)
    ref = arguments.global_reference("Socket")
    if ref is not None and not is_raw and not has_data \
            and _constant_or_absent(arguments, call, "Str") and \
            argument_expression(call, "NoOfBytes", -1) is None:
        # (the text sent is the transition's output, which the machine's steps do not give)
        action.machine = ConstantWrite(ref[1], ((SOCKET_CONNECTED, b""),), None,
                                       "socket_closures", writes=False)
    return action


def _receive_message(m, call, seconds) -> str:
    """The text of one message from the peer, or a socket error."""
    outcome = may_fail(m, "SocketReceive", call.span, _timeouts(m, seconds) + _closures(m))
    if outcome == TIMEOUT:
        raise RapidError("ERR_SOCK_TIMEOUT", "SocketReceive: no message in time")
    if outcome == CLOSED:
        raise RapidError("ERR_SOCK_CLOSED", "SocketReceive: the peer closed the connection")
    text = environment_text(m, "SocketReceive", call.span,
                            site_domain(m, call.span, "socket_messages", "socket_domains", ("",)))
    if text is None:
        m.chooser.socket_input_ended = True
        raise RapidError("ERR_SOCK_CLOSED", "SocketReceive: the client closed the connection "
                         "(end of standard input)")
    return text


@compiled("SocketReceive(VAR socketdev Socket \\VAR string Str | VAR rawbytes RawData | "
              f"VAR anytype Data \\num ReadNoOfBytes \\VAR num NoRecBytes {TIME})",
          modelled=CHOICE)
def _socket_receive(calls, compiler, call, entry):
    has_data = _data_size(compiler, call) is not None
    arguments = Arguments(calls, compiler, call, entry)
    socket, text_ref, raw_ref = arguments.fn("Socket"), arguments.fn("Str"), arguments.fn("RawData")
    data_ref = arguments.fn("Data")
    wanted, received, seconds = (arguments.value("ReadNoOfBytes"), arguments.fn("NoRecBytes"),
                                 arguments.value("Time"))
    is_raw = argument_expression(call, "RawData", -1) is not None
    counts = argument_expression(call, "NoRecBytes", -1) is not None
    if not is_raw and not has_data and argument_expression(call, "Str", -1) is None:
        raise error(UNSUPPORTED, "SocketReceive needs \\Str, \\RawData or \\Data", call.span)

    def receive(m):
        ref = socket(m)
        value = m.read_ref(ref)
        _require(value, SOCKET_CONNECTED, "SocketReceive")
        pending, limit, time = value[1], _optional(wanted(m)), _optional(seconds(m))
        elements = m.read_ref(data_ref(m)) if has_data else ()
        capacity = min(len(elements), rawbytes.MAX_BYTES) if has_data \
            else rawbytes.MAX_BYTES if is_raw else values.STRING_MAX
        _readable_count(limit, capacity, "SocketReceive")
        if is_raw or has_data:
            while not pending or (limit is not None and len(pending) < limit):
                more = rawbytes.from_text(_receive_message(m, call, time))
                if not more:
                    raise RapidError("ERR_SOCK_TIMEOUT", "SocketReceive: the message was empty")
                pending += more
            size = min(len(pending), capacity) if limit is None else int(limit)
            data, pending = pending[:size], pending[size:]
            if has_data:
                m.write_ref(data_ref(m), _stored(elements, data))
            else:
                m.write_ref(raw_ref(m), data)
        else:
            data = (pending.decode("latin-1") if pending
                    else _receive_message(m, call, time))[:80]
            pending = b""
            m.write_ref(text_ref(m), data)
        m.write_ref(ref, (SOCKET_CONNECTED, pending))
        if counts:
            m.write_ref(received(m), float(len(data)))
    action = Action(call.span, receive)
    socket_ref, text_ref_ = arguments.global_reference("Socket"), arguments.global_reference("Str")
    if socket_ref is not None and text_ref_ is not None and not is_raw and not counts and all(
            argument_expression(call, key, -1) is None for key in ("ReadNoOfBytes", "Time")):
        # (the step machine's: a connected socket with no data pending receives a message
        # of the site's domain, unless the check lets the receive fail)
        def texts(config) -> Optional[tuple]:
            if _configured_timeouts(config, None) or _configured_closures(config):
                return None
            return tuple(text[:80] for text in configured_site_domain(
                config, call.span, "socket_messages", "socket_domains", ("",)))
        action.machine = ChosenWrite(text_ref_[1], socket_ref[1], (SOCKET_CONNECTED, b""),
                                     texts)
    return action


# Files, serial channels, rawbytes and controller routines register themselves
# when imported.


# --- reference coverage (issue 8, item 1): UDP datagrams ---------------------------------

@compiled("SocketReceiveFrom(VAR socketdev Socket \\VAR string Str | VAR rawbytes RawData | "
              "VAR anytype Data \\num ReadNoOfBytes \\VAR num NoRecBytes, VAR string RemoteAddress, "
              f"VAR num RemotePort {TIME})",
          modelled=CHOICE)
def _socket_receive_from(calls, compiler, call, entry):
    """One datagram on a bound UDP socket, from the same source as SocketReceive's messages
    (a line of standard input in ``run``, a configured message or a timeout when model
    checking).  The sender is not modelled: RemoteAddress reads "127.0.0.1" and RemotePort 0."""
    has_data = _data_size(compiler, call) is not None
    arguments = Arguments(calls, compiler, call, entry)
    socket, text_ref, raw_ref = arguments.fn("Socket"), arguments.fn("Str"), arguments.fn("RawData")
    data_ref = arguments.fn("Data")
    wanted, received, seconds = (arguments.value("ReadNoOfBytes"), arguments.fn("NoRecBytes"),
                                 arguments.value("Time"))
    address, port = arguments.fn("RemoteAddress"), arguments.fn("RemotePort")
    is_raw = argument_expression(call, "RawData", -1) is not None
    counts = argument_expression(call, "NoRecBytes", -1) is not None
    if not is_raw and not has_data and argument_expression(call, "Str", -1) is None:
        raise error(UNSUPPORTED, "SocketReceiveFrom needs \\Str, \\RawData or \\Data",
                    call.span)

    def receive(m):
        _require(m.read_ref(socket(m)), SOCKET_BOUND, "SocketReceiveFrom")
        limit = _optional(wanted(m))
        elements = m.read_ref(data_ref(m)) if has_data else ()
        capacity = min(len(elements), rawbytes.MAX_BYTES) if has_data \
            else rawbytes.MAX_BYTES if is_raw else values.STRING_MAX
        _readable_count(limit, capacity, "SocketReceiveFrom")
        text = _receive_message(m, call, _optional(seconds(m)))
        if has_data:              # (a datagram: what the array cannot hold is lost)
            data = rawbytes.from_text(text)[:capacity if limit is None else int(limit)]
            m.write_ref(data_ref(m), _stored(elements, data))
        elif is_raw:
            data = rawbytes.from_text(text)
            data = data if limit is None else data[:int(limit)]
            m.write_ref(raw_ref(m), data)
        else:
            data = text[:80] if limit is None else text[:min(80, int(limit))]
            m.write_ref(text_ref(m), data)
        m.write_ref(address(m), "127.0.0.1")
        m.write_ref(port(m), 0.0)
        if counts:
            m.write_ref(received(m), float(len(data)))
    return Action(call.span, receive)
