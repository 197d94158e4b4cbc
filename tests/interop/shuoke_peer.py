#!/usr/bin/python3
"""A Shuoke M6505 stepper drive written from the user's protocol seed alone, for the interop tests.

Usage: shuoke_peer.py PORT ADDRESS [rtu|ascii]

Independent of DriveDesk's code (nothing is imported from it): the framing, the CRC and the
command set are written here from the seed (docs/protocols/shuoke.md is our reading of it).
It answers every request at once, with no wire pacing and no "50 ms between commands" of its
own: the peer a pty pair gives a user who tests against a script. Serves one end of a pty
pair (socat); the baud rate of a pty does not matter. Prints "ready" once it listens and one
line per request it takes: "cmd 0xNN DATA-HEX".

Modelled: handshake 0x20, query address 0x21, baud code 0x23 / 0x24, the speed settings
0x25..0x30 (0..100000, else failure 0x04), relative move 0x31 and jog 0x33 (reached at once,
no acceleration), query speed 0x36 (magnitude), positions 0x37..0x3A, status 0x3B, stops
0x3C / 0x3D, closed-loop positions 0x58..0x5B, gear 0x5F..0x62 (low 16 bits kept).
Failure replies: 0x01 wrong length, 0x02 bad check, 0x03 unknown command, 0x04 out of range.
"""
import os
import select
import sys
import termios
import time
import tty


def crc16(data):
    crc = 0xFFFF
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return bytes([crc & 0xFF, crc >> 8])


def u32(v):
    return (v & 0xFFFFFFFF).to_bytes(4, "little")


def s32(data):
    return int.from_bytes(data, "little", signed=True)


class Drive:
    # command -> data bytes the request carries
    LENGTHS = {0x20: 0, 0x21: 0, 0x22: 1, 0x23: 0, 0x24: 1, 0x31: 4, 0x33: 4, 0x36: 0, 0x37: 0, 0x38: 0,
               0x39: 0, 0x3A: 0, 0x3B: 0, 0x3C: 0, 0x3D: 0, 0x58: 0, 0x59: (0, 4), 0x5A: 0, 0x5B: (0, 4),
               0x5F: 4, 0x60: 0, 0x61: 4, 0x62: 0}
    SPEED_SETS = (0x25, 0x27, 0x29, 0x2B, 0x2D, 0x2F)

    def __init__(self, address):
        self.address = address
        self.baud_code = 6
        self.settings = {0x25: 500, 0x27: 10000, 0x29: 500, 0x2B: 50000, 0x2D: 50000, 0x2F: 5000, 0x5F: 1, 0x61: 1}
        self.position = 0.0  # pulses
        self.offsets = {0x37: 0.0, 0x39: 0.0, 0x58: 0.0, 0x5A: 0.0}
        self.speed = 0.0  # pulses/s, signed
        self.target = None  # a relative move's end
        self.when = time.monotonic()

    def advance(self):
        now = time.monotonic()
        step = self.speed * (now - self.when)
        self.when = now
        if self.target is not None and abs(self.target - self.position) <= abs(step):
            self.position, self.speed, self.target = self.target, 0.0, None
        else:
            self.position += step

    def counter(self, cmd):
        return int(round(self.position - self.offsets[cmd]))

    def handle(self, addr, cmd, data):
        """The reply (addr, cmd, data, failure code or 0) or None."""
        if addr not in (self.address, 0):
            return None
        self.advance()
        if addr == 0 and cmd not in (0x21, 0x3C, 0x3D):
            return (self.address, cmd, b"", 0x05)
        speed_gets = tuple(c + 1 for c in self.SPEED_SETS)
        if cmd in self.SPEED_SETS:
            want = 4
        elif cmd in speed_gets:
            want = 0
        elif cmd in self.LENGTHS:
            want = self.LENGTHS[cmd]
        else:
            return (self.address, cmd, b"", 0x03)
        if len(data) not in (want if isinstance(want, tuple) else (want,)):
            return (self.address, cmd, b"", 0x01)
        reply = b""
        if cmd in self.SPEED_SETS:
            value = int.from_bytes(data, "little")
            if value > 100000:
                return (self.address, cmd, b"", 0x04)
            self.settings[cmd] = value
        elif cmd in speed_gets:
            reply = u32(self.settings[cmd - 1])
        elif cmd == 0x22:
            reply = data
        elif cmd == 0x23:
            reply = bytes([self.baud_code])
        elif cmd == 0x24:
            if not 1 <= data[0] <= 8:
                return (self.address, cmd, b"", 0x04)
            self.baud_code = data[0]
            reply = data
        elif cmd == 0x31:
            distance = s32(data)
            self.target = self.position + distance
            self.speed = float(self.settings[0x27]) * (1 if distance >= 0 else -1)
        elif cmd == 0x33:
            value = s32(data)
            if abs(value) > 100000:
                return (self.address, cmd, b"", 0x04)
            self.speed, self.target = float(value), None
        elif cmd == 0x36:
            reply = u32(int(round(abs(self.speed))))
        elif cmd in (0x37, 0x39, 0x58, 0x5A):
            reply = u32(self.counter(cmd))
        elif cmd in (0x38, 0x3A):
            self.offsets[cmd - 1] = self.position
        elif cmd in (0x59, 0x5B):
            self.offsets[cmd - 1] = self.position - (s32(data) if data else 0)
        elif cmd == 0x3B:
            reply = bytes([1 if self.speed else 0, 0, 0, 0, 1])
        elif cmd in (0x3C, 0x3D):
            self.speed, self.target = 0.0, None
        elif cmd in (0x5F, 0x61):
            value = int.from_bytes(data, "little") & 0xFFFF
            if cmd == 0x61 and value == 0:
                return (self.address, cmd, b"", 0x04)
            self.settings[cmd] = value
        elif cmd in (0x60, 0x62):
            reply = u32(self.settings[cmd - 1])
        if addr == 0 and cmd != 0x21:
            return None
        return (self.address, cmd, reply, 0)


def rtu_frames(buffer):
    """Complete frames at the front of `buffer`: yields (frame bytes, check ok) and the rest."""
    out = []
    while len(buffer) >= 5:
        length = buffer[2]
        if length > 16 or buffer[1] & 0x80:
            buffer = buffer[1:]
            continue
        size = 5 + length
        if len(buffer) < size:
            break
        frame = buffer[:size]
        ok = crc16(frame[:-2]) == frame[-2:] or frame[1] == 0x20  # 0x20: 不做CRC数据检查
        out.append((frame[:-2], ok))
        buffer = buffer[size:]
    return out, buffer


def ascii_frames(buffer):
    out = []
    while True:
        start = buffer.find(b":")
        if start < 0:
            return out, b""
        end = buffer.find(b"\n", start)
        if end < 0:
            return out, buffer[start:]
        text = buffer[start + 1:end].rstrip(b"\r")
        buffer = buffer[end + 1:]
        try:
            raw = bytes.fromhex(text.decode("ascii"))
        except ValueError:
            continue
        if len(raw) < 4:
            continue
        out.append((raw[:-1], sum(raw[:-1]) & 0xFF == raw[-1]))  # 和校验: low 8 bits of the sum


def encode(framing, addr, cmd, data, failure):
    body = bytes([addr, cmd | 0x80, 1, failure]) if failure else bytes([addr, cmd, len(data)]) + data
    if framing == "ascii":
        return b":" + (body + bytes([sum(body) & 0xFF])).hex().upper().encode("ascii") + b"\r\n"
    return body + crc16(body)


def main():
    port, address = sys.argv[1], int(sys.argv[2])
    framing = sys.argv[3] if len(sys.argv) > 3 else "rtu"
    drive = Drive(address)
    fd = os.open(port, os.O_RDWR | os.O_NOCTTY)
    tty.setraw(fd)
    attrs = termios.tcgetattr(fd)
    attrs[4] = attrs[5] = termios.B9600
    termios.tcsetattr(fd, termios.TCSANOW, attrs)
    print("ready", flush=True)
    buffer = b""
    while True:
        readable, _, _ = select.select([fd], [], [], 0.02)
        if not readable:
            buffer = b""  # a silence ends whatever was incomplete
            continue
        buffer += os.read(fd, 256)
        frames, buffer = (ascii_frames if framing == "ascii" else rtu_frames)(buffer)
        for body, ok in frames:
            addr, cmd, data = body[0], body[1], body[3:]
            if not ok:
                if addr == drive.address:
                    os.write(fd, encode(framing, addr, cmd, b"", 0x02))
                continue
            reply = drive.handle(addr, cmd, data)
            if reply is None:
                continue
            print("cmd 0x%02X %s" % (cmd, data.hex()), flush=True)
            os.write(fd, encode(framing, *reply))


if __name__ == "__main__":
    main()
