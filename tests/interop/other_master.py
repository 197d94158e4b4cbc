#!/usr/bin/python3
"""Another Modbus master on the line, for the busy-line interop test.

Usage: other_master.py PORT INTERVAL_MS

Writes a read request to address 9 (03, register 0, one register) every INTERVAL_MS, for
ever, and reads (and ignores) whatever comes: below the Modbus silence (1.75 ms above 19200
baud) the line is never quiet. Prints "ready" once it
has the port. Its own CRC, nothing imported from DriveDesk.
"""
import os
import sys
import time


def crc16(data):
    crc = 0xFFFF
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return bytes([crc & 0xFF, crc >> 8])


def main():
    fd = os.open(sys.argv[1], os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
    interval = float(sys.argv[2]) / 1000.0
    frame = bytes([9, 3, 0, 0, 0, 1])
    frame += crc16(frame)
    print("ready", flush=True)
    while True:
        os.write(fd, frame)
        try:
            os.read(fd, 4096)
        except BlockingIOError:
            pass
        time.sleep(interval)


if __name__ == "__main__":
    main()
