#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets: tests/fuzz/corpus/<target>/<name>.

The frames are the seeds' worked examples (docs/protocols/) and the unit tests' vectors
(tests/unit/tst_*.cpp), plus a few broken ones; each file starts with the control bytes the
target reads first (see the comment at the top of tests/fuzz/fuzz_<target>.cpp). The JSON
loaders read tests/data/{backup,dictionaries,alarms}/ and resources/ as further seed folders
(tests/fuzz/CMakeLists.txt); here they get only a few edge cases.

Every committed file is replayed by the ctest test fuzz_<target>_corpus. Crash reproducers
found by fuzzing go into the same folders under a name saying what they caught (keep those:
this script only rewrites the files it generates). Run from anywhere: python3 make-seeds.py
"""
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, '..', 'data')
CORPUS = os.path.join(HERE, 'corpus')


def h(text):
    return bytes.fromhex(text.replace(' ', ''))


def crc16(data):
    crc = 0xFFFF
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return crc


def with_crc(data):
    return data + struct.pack('<H', crc16(data))


def u16(v):
    return struct.pack('<H', v)


def u32(v):
    return struct.pack('<I', v)


def segments(frames, noise=b''):
    """The segment form of tests/fuzz/fuzzsupport.h segmentsWithCrc(): each frame (CRC
    included) becomes [0x80 | length without CRC][bytes without CRC]; noise is one plain
    segment in front."""
    out = bytes([len(noise)]) + noise if noise else b''
    for f in frames:
        out += bytes([0x80 | (len(f) - 2)]) + f[:-2]
    return out


def write(target, name, data):
    folder = os.path.join(CORPUS, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, 'seed-' + name), 'wb') as f:
        f.write(data)


def servocan():
    frames = {  # docs/protocols/servo-can.md (station 0) and tst_servocancodec.cpp
        'keep-alive': '00080000000000ff',
        'enable-on': '00250100000000ff',
        'speed-100': '00200064000000ff',
        'positioning-speed-200': '002300c8000000ff',
        'relative-1000': '002100e8030000ff',
        'absolute-1000': '002200e8030000ff',
        'heartbeat-b7-00': '0010001234567800',
        'heartbeat': '00100012345678ff',
        'read-speed': '0012fc00000000ff',
        'read-param-4': '0012fa04000000ff',
        'write-param-75': '0015014b000a00ff',
        'alarm': '00053412000000ff',
        'clear-alarm': '00810000000000ff',
        'bad-command': '00990000000000ff',
        'bad-read-type': '0012ee00000000ff',
        'bad-index': '0012fadc000000ff',
    }
    for name, data in frames.items():
        write('fuzz_servocan', name, b'\x00' + u32(0x64) + h(data))
    # station 42 (tst_servocancodec.cpp), an extended ID, a short DLC
    write('fuzz_servocan', 'station-42-read', b'\x00' + u32(0x64 + 42) + h('2a120000000000ff'))
    write('fuzz_servocan', 'extended', b'\x01' + u32(0x64) + h('00080000000000ff'))
    write('fuzz_servocan', 'dlc-7', b'\x00' + u32(0x64) + h('00080000000000'))


MODBUS_REQUESTS = {  # tst_modbusrtu.cpp, tst_modbusrtuparser.cpp
    'read-0x6b-3': '1103006b00037687',
    'write-single': '110600010003 9a9b',
    'write-multiple': '1110000100020400 0a0102 c6f0',
    'read-monitor': with_crc(h('0503000000 18')).hex(),
    'read-pa': with_crc(h('05030064 0014')).hex(),
    'ee-legacy': '050600000001 498e',
    'ee-new': '0510003a00010200 01500a',
    'write-pa-2': '05100064000204 0001fffe 70f4',
    'read-count-0': with_crc(h('010300000000')).hex(),
    'read-bad-crc': '01030000000ac5cd',
    'unknown-function': '0504000000 01304e',
}

MODBUS_REPLIES = {  # name: (request address, function, start, count, reply)
    'read-3': (0x11, 0x03, 0x006B, 3, '1103 06 ae41 5652 4340 49ad'),
    'read-2': (0x05, 0x03, 0x0064, 2, '050304 0001 fffe 2e43'),
    'write-single': (0x11, 0x06, 0x0001, 1, '110600010003 9a9b'),
    'write-multiple': (0x11, 0x10, 0x0001, 2, '111000010002 1298'),
    'exception-03': (0x01, 0x03, 0x0000, 10, '01830440f3'),
    'exception-06': (0x01, 0x06, 0x0000, 1, '01860443a3'),
    'exception-10': (0x01, 0x10, 0x0000, 1, '0190044dc3'),
    'exception-other-address': (0x05, 0x03, 0x0000, 1, '01830440f3'),
    'ee-legacy-progress': (0x05, 0x06, 0x0000, 1, with_crc(h('050600000000')).hex()),
    'read-bad-crc': (0x11, 0x03, 0x006B, 3, '1103 06 ae41 5652 4340 49ae'),
}


def modbus():
    for name, data in MODBUS_REQUESTS.items():
        write('fuzz_modbusrtu_request', name, b'\x00\x00' + h(data))
        write('fuzz_modbusrtu_request', name + '-max20-repair-crc', b'\x01\x14' + h(data))
    selector = {0x03: 0, 0x06: 1, 0x10: 2}
    for name, (addr, fc, start, count, data) in MODBUS_REPLIES.items():
        request = bytes([addr, selector[fc]]) + u16(start) + u16(count)
        write('fuzz_modbusrtu_reply', name, b'\x00' + request + h(data))
        write('fuzz_modbusrtu_reply', name + '-repair-crc', b'\x01' + request + h(data))

    # Streams: frames back to back, with noise, local echo and a truncated frame.
    reqs = [h(MODBUS_REQUESTS[n]) for n in ('read-0x6b-3', 'write-single', 'write-multiple', 'ee-new')]
    reps = [h(MODBUS_REPLIES[n][4]) for n in ('read-3', 'write-single', 'write-multiple', 'exception-03')]
    streams = {
        'requests': (0, b''.join(reqs)),
        'requests-noise': (0, b'\x00\xff\x10' + reqs[0] + b'\xaa' + reqs[2][:5] + reqs[1]),
        'requests-cap-45': (2 * 37, b''.join(reqs)),
        'replies': (1, b''.join(reps)),
        'replies-echo': (1, reqs[0] + reps[0]),
        'replies-noise': (1, b'\xfe\xff' + reps[3] + b'\x00' + reps[0][:4] + reps[1]),
        'replies-claims-long': (1, h('0503fe') + reps[1]),
    }
    for name, (control, data) in streams.items():
        write('fuzz_modbusrtu_parser', name, bytes([control, 0xff, 0]) + data)
        write('fuzz_modbusrtu_parser', name + '-bytewise', bytes([control, 0, 0]) + data)
    write('fuzz_modbusrtu_parser', 'requests-segments', bytes([0, 3, 1]) + segments(reqs, b'\x01\x10\x00'))
    write('fuzz_modbusrtu_parser', 'replies-segments', bytes([1, 3, 1]) + segments(reps, b'\x05\x03'))


SHUOKE_RTU = {  # tst_shuokertu.cpp and the seed's examples
    'handshake': with_crc(h('012000')).hex(),
    'query-address': '0021006990',
    'change-address': with_crc(h('01220102')).hex(),
    'get-baud-reply': '01240106c041',
    'set-start-speed': '012504e80300003895',
    'speed-reply': with_crc(h('013604a0860100')).hex(),
    'relative-dir24': '01320401400d03baab',
    'run-dir24': '01340400e803007eb0',
    'status-reply': '013b050100010001a691',
    'io-reply': '01410501010000012d6a',
    'failure-reply': '01a5010411a8',
    'failure-bad-len': '01a5020400',
    'negative-position': '01370418fcffff3967',
    'len-counts-crc': with_crc(h('013606a0860100')).hex(),
    'fixed-length': with_crc(h('0136 00 0000000000')).hex(),
    'fixed-length-2': with_crc(h('0124 01 06 00000000')).hex(),
    'bad-crc': '013604a08601003def',
    'handshake-no-crc': '0120000000',
    'home': '013e003060',
    'homing-4e': '014e0101a19f',
}


def ascii_frame(data, twos=False):
    s = sum(data) & 0xFF
    if twos:
        s = (-s) & 0xFF
    return b':' + (data + bytes([s])).hex().upper().encode() + b'\r\n'


SHUOKE_ASCII = {  # tst_shuokeascii.cpp and the seed's worked example
    'change-address': b':0122010226\r\n',
    'change-address-lf': b':0122010226\n',
    'lower-case': b':01220102da\r\n',
    'twos-complement': b':01220102DA\r\n',
    'len-plus-one': b':0122020227\r\n',
    'speed-reply': b':013604A086010062\r\n',
    'start-speed': b':012504E803000015\r\n',
    'status-reply': b':013B05010001000144\r\n',
    'failure': b':01A5010455\r\n',
    'failure-len-2': b':01A5020400AC\r\n',
    'query-address': b':00210021\r\n',
    'bad-check': b':0122010227\r\n',
    'non-hex': b':01220G0226\r\n',
    'odd-digits': b':012201022\r\n',
}


def shuoke():
    for name, data in SHUOKE_RTU.items():
        for control in (0, 3, 7, 11):
            write('fuzz_shuoke_rtu', '%s-opt%d' % (name, control), bytes([control]) + h(data))
    rtu = [h(SHUOKE_RTU[n]) for n in ('change-address', 'speed-reply', 'status-reply', 'failure-reply',
                                       'len-counts-crc', 'fixed-length')]
    streams = {
        'frames': b''.join(rtu),
        'noise': b'\x00\xff\x36' + rtu[1] + b'\x01\x36\x10' + rtu[0] + rtu[2][:6] + rtu[3],
        'truncated-then-frame': rtu[2][:7] + rtu[1],
    }
    for name, data in streams.items():
        for control in (0x3, 0x0, 0xF):
            write('fuzz_shuoke_rtu_parser', '%s-opt%d' % (name, control), bytes([control, 0, 0xff]) + data)
        write('fuzz_shuoke_rtu_parser', name + '-bytewise', bytes([0x3, 0, 0]) + data)
    write('fuzz_shuoke_rtu_parser', 'segments', bytes([0x13, 0, 4]) + segments(rtu, b'\x01\x36\x04'))
    write('fuzz_shuoke_rtu_parser', 'segments-feed', bytes([0x1B, 0, 0xff]) + segments(rtu))

    for name, line in SHUOKE_ASCII.items():
        control = 1 if name in ('lower-case', 'twos-complement') else 2
        write('fuzz_shuoke_ascii', name, bytes([control]) + line)
        write('fuzz_shuoke_ascii', name + '-repair-check', bytes([control | 4]) + line)
    stream = b''.join(SHUOKE_ASCII[n] for n in ('change-address', 'speed-reply', 'bad-check', 'failure'))
    write('fuzz_shuoke_ascii_parser', 'lines', bytes([2, 0, 0xff]) + stream)
    write('fuzz_shuoke_ascii_parser', 'lines-bytewise', bytes([2, 0, 0]) + stream)
    write('fuzz_shuoke_ascii_parser', 'garbage-and-interrupted',
          bytes([2, 0, 5]) + b'xx:01220:0122010226\r\n:01X2010226\r\n:0222010227\r\n')
    ascii_segments = b''
    for n in ('change-address', 'speed-reply', 'failure'):
        body = bytes.fromhex(SHUOKE_ASCII[n][1:].strip().decode())[:-1]
        ascii_segments += bytes([0x80 | len(body)]) + body
    write('fuzz_shuoke_ascii_parser', 'segments', bytes([6, 0, 0xff]) + b'\x03x:0' + ascii_segments)
    write('fuzz_shuoke_ascii_parser', 'too-long', bytes([2, 0, 0xff]) + b':' + b'0' * 60 + b'\r\n'
          + SHUOKE_ASCII['status-reply'])

    can = {  # tst_shuokecan.cpp: id = address, data = RTU frame without CRC, padded to 8
        'query-speed': (1, False, '0136000000000000'),
        'speed-reply': (1, False, '013604a086010000'),
        'start-speed': (1, False, '012504e8030000 00'),
        'failure': (1, False, '01b6010400000000'),
        'extended-zero-id': (0, True, '0136000000000000'),
        'extended-address-id': (7, True, '0736000000000000'),
        'short-dlc': (1, False, '01360100'),
        'len-beyond-dlc': (1, False, '013604000000'),
        'id-differs': (2, False, '0136000000000000'),
    }
    for name, (cid, ext, data) in can.items():
        write('fuzz_shuoke_can', name, bytes([1 if ext else 0]) + u32(cid) + h(data))

    # PLC: reply mode [0][base][request addr][cmd][data len][data][ADU]; request mode [1][base][ADU]
    plc_replies = {  # tst_shuokeplc.cpp
        'speed-read': (0, 1, 0x36, '', '010304a0860100384a'),
        'baud-read': (0, 1, 0x23, '', with_crc(h('01030406000000')).hex()),
        'set-address': (0, 1, 0x22, '02', '011000220002e1c2'),
        'direction-5c': (0, 1, 0x5C, '01', '0110005c0001c1db'),
        'exception': (0, 1, 0x36, '', '018302c0f1'),
        'status': (0, 1, 0x3B, '', with_crc(h('010308 0100010001000000')).hex()),
        'broadcast': (0, 0, 0x22, '02', '021000220002e1f1'),
        'base-0x100': (0x100, 1, 0x36, '', '010304a0860100384a'),
    }
    for name, (base, addr, cmd, data, adu) in plc_replies.items():
        d = h(data)
        write('fuzz_shuoke_plc', 'reply-' + name, b'\x00' + u16(base) + bytes([addr, cmd, len(d)]) + d + h(adu))
        write('fuzz_shuoke_plc', 'reply-' + name + '-repair-crc',
              b'\x02' + u16(base) + bytes([addr, cmd, len(d)]) + d + h(adu))
    plc_requests = {
        'read-speed': with_crc(h('010300360002')).hex(),
        'set-address': '011000220002040200000071d6',
        'set-baud': '0110002400020406000000f0cc',
        'direction-5c': '0110005c0001020100ab5c',
        'clear-0x38': '0110003800020400000000f11d',
        'handshake': '0003002100001411',
        'status': '0103003b000435c4',
    }
    for name, adu in plc_requests.items():
        write('fuzz_shuoke_plc', 'request-' + name, b'\x01' + u16(0) + h(adu))
        write('fuzz_shuoke_plc', 'request-' + name + '-repair-crc', b'\x03' + u16(0) + h(adu))


def json_loaders():
    # The loaders' main seeds are tests/data/{backup,dictionaries,alarms}/ and the bundled
    # tables in resources/ (tests/fuzz/CMakeLists.txt passes those folders too). Here: edge cases.
    for target in ('fuzz_backupfile', 'fuzz_parameterdictionary', 'fuzz_alarmdictionary'):
        write(target, 'empty-object.json', b'{}')
        write(target, 'array.json', b'[1, 2.5e308, -0, "\\u0000", null, true]')
        write(target, 'bom.json', b'\xef\xbb\xbf{"format": 1}')
    write('fuzz_backupfile', 'minimal-servo-can.json',
          b'{"format":"drivedesk-backup","formatVersion":1,"toolVersion":"0.1.0",'
          b'"created":"2024-05-01T08:30:00Z","family":"servo-can","address":0,"firmware":"",'
          b'"model":"","link":{},"parameters":[],"checksum":'
          b'"sha256:e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"}')
    write('fuzz_alarmdictionary', 'fallback-only.json',
          '{"format":"drivedesk-alarms","formatVersion":1,"family":"shuoke",'
          '"fallback":{"en":"Alarm %1","zh":"报警 %1"},"alarms":[{"code":-2147483648,'
          '"text":{"en":"x","zh":"y"}}]}'.encode('utf-8'))


def framedescriber():
    """[family: 0 servo-can, 1 servo-modbus, 2 shuoke][framing: 0 rtu 1 ascii 2 plc 3 can]
    [options], then frames [h][length][CAN: id u32][bytes] (tests/fuzz/fuzz_framedescriber.cpp)."""
    def serial(frame, drive=False, repair=False, reset=False):
        return bytes([(1 if drive else 0) | (8 if repair else 0) | (16 if reset else 0), len(frame)]) + frame

    def can(can_id, frame, drive=False, extended=False):
        return bytes([2 | (1 if drive else 0) | (4 if extended else 0), len(frame)]) + u32(can_id) + frame

    t = 'fuzz_framedescriber'
    write(t, 'servo-can-traffic', bytes([0, 3, 0])
          + can(0x64, h('00080000000000ff')) + can(0x64, h('00108800000000ff'), True)
          + can(0x64, h('00200064000000ff')) + can(0x64, h('0012fa4b000000ff'))
          + can(0x64, h('0012fa4b000000ff'), True) + can(0x64, h('00050e00000000ff'), True)
          + can(0x64, h('0008000000'), extended=True))
    read = with_crc(h('010300640014'))
    reply = with_crc(bytes([1, 3, 40]) + bytes(range(40)))
    write(t, 'servo-modbus-request-reply', bytes([1, 0, 0]) + serial(read) + serial(reply, True)
          + serial(h('0183020000'), True, repair=True)
          + serial(with_crc(h('0110006400020400010002')))
          + serial(reply, True, reset=True))
    write(t, 'shuoke-rtu', bytes([2, 0, 0]) + serial(with_crc(h('012800'))) + serial(with_crc(h('012804a0860100')), True)
          + serial(with_crc(h('01a80101')), True) + serial(h('0128'), True))
    write(t, 'shuoke-ascii', bytes([2, 1, 1]) + serial(b':01280029\r\n') + serial(b':012804A086010054\r\n', True)
          + serial(b':0122010226\r\n'))
    write(t, 'shuoke-plc', bytes([2, 2, 2]) + serial(with_crc(h('010300280002'))) + serial(with_crc(h('010304a0860100')), True))
    write(t, 'shuoke-can', bytes([2, 3, 0]) + can(1, h('0128000000000000')) + can(1, h('012804a086010000'), True)
          + can(0, h('2100000000000000')) + can(1, h('01'), True, extended=True))


def main():
    # Only generated files are replaced; crash reproducers (not "seed-*") stay.
    if os.path.isdir(CORPUS):
        for target in os.listdir(CORPUS):
            folder = os.path.join(CORPUS, target)
            for name in os.listdir(folder):
                if name.startswith('seed-'):
                    os.remove(os.path.join(folder, name))
    servocan()
    modbus()
    shuoke()
    json_loaders()
    framedescriber()
    for target in sorted(os.listdir(CORPUS)):
        print('%-28s %3d files' % (target, len(os.listdir(os.path.join(CORPUS, target)))))


if __name__ == '__main__':
    main()
