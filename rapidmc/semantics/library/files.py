"""Files and serial channels (iodev): Open, Close, Write..., Read....

Like sockets, files are the environment: nothing touches the disk.  Text
written to an open device is printed as ``[file NAME] <line>`` (a line is
printed when it is complete, or at Close); reads take one line of standard
input in ``run`` mode (end of input is end of file) and, when model
checking, a choice among the configured lines or end of file.

An ``iodev`` variable holds ``None`` (closed) or ``(name, mode, unread,
unwritten)``: the device name (``HOME:/log.txt``, ``com1:``), the access
mode (``read``, ``write`` or ``append``, followed by `` bin`` when opened with
\\Bin), received text not read yet (ReadBin/ReadStrBin read characters, not
lines; ReadRawBytes on a binary device takes a line of hex pairs as the bytes it
stands for), and written text not ended by a new line yet.
"""
from __future__ import annotations

from .. import rawbytes, values
from ..errors import RapidError
from ..expressions import Compiled
from ..instructions import Action
from ..machine import ABSENT
from ..types import NUM, STRING
from .arguments import Arguments
from .data import PREDEFINED_DATA
from .flexpendant import TP_OPTIONS
from .registry import CHOICE, compiled
from .signature_parts import DEVICE, TIME
from .environment_model import site_domain
from .sockets import environment_text

EOF_TEXT = PREDEFINED_DATA["EOF"].value
EOF_NUM = float(PREDEFINED_DATA["EOF_NUM"].value)
EOF_BIN = -1.0
READ, WRITE, APPEND, BINARY = "read", "write", "append", "bin"


def _open_device(m, ref, what: str, writing: bool = False):
    value = m.read_ref(ref)
    if value is None:
        raise RapidError("ERR_FILEACC", f"{what}: the I/O device is not open")
    if writing and value[1].split()[0] == READ:
        raise RapidError("ERR_FILEACC", f"{what}: {value[0]} is open for reading only")
    return value


def _emit(m, name: str, text: str) -> str:
    """Print the complete lines of ``text``; return the unfinished rest."""
    *lines, rest = text.split("\n")
    for line in lines:
        m.output.append(f"[file {name}] {line}")
    return rest


def _writer(calls, compiler, call, entry, text_of):
    """An instruction appending ``text_of(m, arguments)`` to an open device."""
    arguments = Arguments(calls, compiler, call, entry)
    device = arguments.fn("IODevice")
    what = call.name.text

    def write(m):
        ref = device(m)
        name, mode, unread, unwritten = _open_device(m, ref, what, writing=True)
        rest = _emit(m, name, unwritten + text_of(m, arguments))
        m.write_ref(ref, (name, mode, unread, rest))
    return Action(call.span, write)


# \Read, \Write and \Append exclude each other; \Bin goes with any of them (`\Read\Bin`,
# `\Write\Bin` in public programs that run on controllers, e.g. abb_motion_program_exec).
@compiled(f"Open(string Object \\string File, {DEVICE} \\switch Read | switch Write | switch Append "
              "\\switch Bin)")
def _open(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    place, file, device = arguments.value("Object"), arguments.value("File"), arguments.fn("IODevice")
    modes = [(arguments.value(key), mode) for key, mode in (("Read", READ), ("Append", APPEND))]
    binary = arguments.value("Bin")

    def open_device(m):
        ref = device(m)
        if m.read_ref(ref) is not None:
            raise RapidError("ERR_FILEOPEN", "Open: the I/O device is already open")
        name = place(m)
        extra = file(m)
        if extra is not ABSENT:
            name = name.rstrip("/") + "/" + extra
        mode = next((mode for flag, mode in modes if flag(m) is True), WRITE)
        if binary(m) is True:
            mode = f"{mode} {BINARY}"
        m.write_ref(ref, (name, mode, "", ""))
    return Action(call.span, open_device)


@compiled(f"Close({DEVICE})")
def _close(calls, compiler, call, entry):
    device = Arguments(calls, compiler, call, entry).fn("IODevice")

    def close(m):
        ref = device(m)
        value = m.read_ref(ref)
        if value is not None and value[3]:
            m.output.append(f"[file {value[0]}] {value[3]}")
        m.write_ref(ref, None)
    return Action(call.span, close)


def _write_text(m, arguments) -> str:
    text = arguments.value("String")(m)
    for key, kind in TP_OPTIONS:
        value = arguments.value(key)(m)
        if value is not ABSENT:
            text += values.format_value(value, kind)
    return text if arguments.value("NoNewLine")(m) is True else text + "\n"


@compiled(f"Write({DEVICE}, string String \\num Num | bool Bool | pos Pos | orient Orient "
              "| dnum Dnum \\switch NoNewLine)")
def _write(calls, compiler, call, entry):
    return _writer(calls, compiler, call, entry, _write_text)


@compiled(f"WriteStrBin({DEVICE}, string Str)")
def _write_str_bin(calls, compiler, call, entry):
    return _writer(calls, compiler, call, entry, lambda m, a: a.value("Str")(m))


def _byte_text(data) -> str:
    return rawbytes.to_text(bytes(data)) + "\n"


@compiled(f"WriteBin({DEVICE}, num Buffer{{*}}, num NChar)")
def _write_bin(calls, compiler, call, entry):
    def text_of(m, arguments):
        buffer, count = arguments.value("Buffer")(m), arguments.value("NChar")(m)
        if count != int(count) or not 0 <= count <= len(buffer):
            raise RapidError("ERR_OUTOFBND", f"NChar {count:g} is outside the buffer")
        return _byte_text(int(b) & 0xFF for b in buffer[:int(count)])
    return _writer(calls, compiler, call, entry, text_of)


@compiled(f"WriteRawBytes({DEVICE}, VAR rawbytes RawData \\num NoOfBytes)")
def _write_raw_bytes(calls, compiler, call, entry):
    def text_of(m, arguments):
        data = rawbytes.as_bytes(arguments.value("RawData")(m))
        count = arguments.value("NoOfBytes")(m)
        return _byte_text(data if count is ABSENT else data[:int(count)])
    return _writer(calls, compiler, call, entry, text_of)


@compiled(f"ClearIOBuff({DEVICE})")
def _clear_io_buff(calls, compiler, call, entry):
    device = Arguments(calls, compiler, call, entry).fn("IODevice")

    def clear(m):
        ref = device(m)
        name, mode, _, unwritten = _open_device(m, ref, "ClearIOBuff")
        m.write_ref(ref, (name, mode, "", unwritten))
    return Action(call.span, clear)


@compiled(f"Rewind({DEVICE})")
def _rewind(calls, compiler, call, entry):
    device = Arguments(calls, compiler, call, entry).fn("IODevice")
    return Action(call.span, lambda m: _open_device(m, device(m), "Rewind"))


# ===========================================================================
# Reading
# ===========================================================================

def _next_line(m, call, name: str):
    """The next line of the device's input, or None at end of file."""
    lines = site_domain(m, call.span, "file_lines", "file_domains", ("",))
    domain = lines if EOF_TEXT in lines else lines + (EOF_TEXT,)
    text = environment_text(m, f"{call.name.text} {name}", call.span, domain)
    return None if text is None or (m.chooser.check_mode and text == EOF_TEXT) else text


def _reader(calls, compiler, call, entry, read, result_type) -> Compiled:
    """A function reading from an open device: ``read(m, arguments, name, unread)``
    returns (value, unread left)."""
    arguments = Arguments(calls, compiler, call, entry)
    device = arguments.fn("IODevice")

    def read_device(m):
        ref = device(m)
        name, mode, unread, unwritten = _open_device(m, ref, call.name.text)
        value, unread = read(m, arguments, name, unread)
        m.write_ref(ref, (name, mode, unread, unwritten))
        return value
    return Compiled(read_device, result_type)


def _characters(m, call, name: str, unread: str, count: int):
    """At least ``count`` characters of input (fewer only at end of file)."""
    while len(unread) < count:
        line = _next_line(m, call, name)
        if line is None:
            break
        unread += line + "\n"
    return unread


def _binary_characters(m, call, name: str, unread: str, count: int):
    """At least ``count`` bytes of a device opened with \\Bin (fewer only at end of file),
    as Latin-1 characters: a line of input gives the bytes it stands for, hex pairs as in
    ``--socket-messages`` (``"0a 1F"``), else its characters, without a line end."""
    while len(unread) < count:
        line = _next_line(m, call, name)
        data = rawbytes.from_text(line).decode("latin-1") if line is not None else ""
        if not data:            # end of file, or an empty line: no more bytes now
            break
        unread += data
    return unread


# \Delim (RobotWare 6 manual, ReadStr): the characters of the string end the significant part
# of the text as the line feed does; the rest of the line is left for the next read.
# \DiscardHeaders skips delimiters before the significant part.
@compiled(f"string ReadStr({DEVICE} \\string Delim \\switch RemoveCR \\switch DiscardHeaders {TIME})",
          modelled=CHOICE)
def _read_str(calls, compiler, call, entry) -> Compiled:
    def read(m, arguments, name, unread):
        delimiters = arguments.value("Delim")(m)
        if not unread:
            line = _next_line(m, call, name)
            if line is None:
                return EOF_TEXT, ""
            unread = line + "\n"
        ends = "\n" + ("" if delimiters is ABSENT else delimiters)
        if arguments.value("DiscardHeaders")(m) is True:
            unread = unread.lstrip(ends) or unread[-1:]
        cut = next((i for i, character in enumerate(unread) if character in ends), len(unread))
        return unread[:cut][:80], unread[cut + 1:]
    return _reader(calls, compiler, call, entry, read, STRING)


@compiled(f"num ReadNum({DEVICE} \\string Delim {TIME})",
          modelled=CHOICE)
def _read_num(calls, compiler, call, entry) -> Compiled:
    def read(m, arguments, name, unread):
        line = unread.partition("\n")[0] if unread else _next_line(m, call, name)
        if line is None:
            return EOF_NUM, ""
        try:
            return values.to_num(float(line.strip())), ""
        except ValueError:
            raise RapidError("ERR_RCVDATA", f"ReadNum: {line!r} is not a number") from None
    return _reader(calls, compiler, call, entry, read, NUM)


@compiled(f"num ReadBin({DEVICE} {TIME})",
          modelled=CHOICE)
def _read_bin(calls, compiler, call, entry) -> Compiled:
    def read(m, arguments, name, unread):
        unread = _characters(m, call, name, unread, 1)
        if not unread:
            return EOF_BIN, ""
        return float(ord(unread[0]) & 0xFF), unread[1:]
    return _reader(calls, compiler, call, entry, read, NUM)


@compiled(f"string ReadStrBin({DEVICE}, num NoOfChars {TIME})",
          modelled=CHOICE)
def _read_str_bin(calls, compiler, call, entry) -> Compiled:
    def read(m, arguments, name, unread):
        count = arguments.value("NoOfChars")(m)
        if count != int(count) or not 1 <= count <= 80:
            raise RapidError("ERR_ARGVALERR", f"NoOfChars must be 1..80, not {count:g}")
        unread = _characters(m, call, name, unread, int(count))
        if not unread:
            return EOF_TEXT, ""
        return unread[:int(count)], unread[int(count):]
    return _reader(calls, compiler, call, entry, read, STRING)


# ABB's examples read what the device has (`ReadRawBytes io_device, raw_data_in \Time:=1;`):
# without \NoOfBytes the read takes the received data not read yet, or else the next line,
# at most a full rawbytes (1024 bytes); at the end of the file RawData is empty.
@compiled(f"ReadRawBytes({DEVICE}, VAR rawbytes RawData \\num NoOfBytes {TIME})",
          modelled=CHOICE)
def _read_raw_bytes(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    device, target, count = arguments.fn("IODevice"), arguments.fn("RawData"), \
        arguments.value("NoOfBytes")

    def read(m):
        ref = device(m)
        name, mode, unread, unwritten = _open_device(m, ref, "ReadRawBytes")
        wanted = count(m)
        more = _binary_characters if mode.endswith(BINARY) else _characters
        if wanted is ABSENT:
            unread = more(m, call, name, unread, 1)
            size = min(len(unread), rawbytes.MAX_BYTES)
        else:
            size = int(wanted)
            unread = more(m, call, name, unread, size)
        m.write_ref(target(m), unread[:size].encode("latin-1", errors="replace"))
        m.write_ref(ref, (name, mode, unread[size:], unwritten))
    return Action(call.span, read)
