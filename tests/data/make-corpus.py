#!/usr/bin/env python3
"""Regenerates the file corpus under tests/data/ (backups, dictionaries, alarm tables).

good/ files must load; bad/ files are named <error>--<what>.json where <error> is the
dd::errorCodeName() of the error the loader must report. The tests check every file, and
the fuzz targets use the directories as seeds. Run from anywhere: python3 make-corpus.py
"""
import copy, hashlib, json, os

HERE = os.path.dirname(os.path.abspath(__file__))


def checksum(params):
    canon = ''.join('%d=%d\n' % (p['index'], p['value']) for p in sorted(params, key=lambda p: p['index']))
    return 'sha256:' + hashlib.sha256(canon.encode('ascii')).hexdigest()


def entry(index, key, name, value, unit='', access='rw'):
    e = {'index': index, 'key': key, 'name': name, 'value': value, 'unit': unit, 'access': access}
    if access == 'wo':
        e['lastWritten'] = True
    return e


def backup(family, params, **meta):
    doc = {'format': 'drivedesk-backup', 'formatVersion': 1, 'toolVersion': '0.1.0',
           'created': '2024-05-01T08:30:00Z', 'family': family, 'address': 1,
           'firmware': '', 'model': '', 'link': {}, 'parameters': params}
    doc.update(meta)
    doc['checksum'] = checksum(params)
    return doc


def modbus():
    return backup('servo-modbus', [entry(0, 'PA0', 'Parameter PA0', 12), entry(1, 'PA1', 'Parameter PA1', -5),
                                   entry(2, 'PA2', 'Firmware version', 7051, access='ro'),
                                   entry(51, 'PA51', 'Drive address', 1)],
                  firmware='7051', link={'port': '/dev/ttyUSB0', 'baud': 19200, 'framing': '8N1'})


def shuoke():
    return backup('shuoke', [entry(36, 'baud-code', 'Serial baud rate code', 6),
                             entry(37, 'start-speed', 'Start speed', 500, 'pulse/s'),
                             entry(39, 'max-speed', 'Maximum speed', 20000, 'pulse/s'),
                             entry(92, 'encoder-direction', 'Encoder direction', 1, access='wo'),
                             entry(101, 'encoder-ab-tolerance', 'Encoder A/B error tolerance', 200, 'pulse', 'wo')],
                  address=3, model='M6505', link={'port': 'COM3', 'baud': 9600, 'framing': 'rtu'})


def rehash(doc):
    doc['checksum'] = checksum(doc['parameters'])
    return doc


def write(sub, name, doc=None, raw=None):
    path = os.path.join(HERE, sub, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    data = raw if raw is not None else (json.dumps(doc, ensure_ascii=False, indent=4) + '\n').encode('utf-8')
    with open(path, 'wb') as f:
        f.write(data)


def mutate(base, fn, fix_checksum=False):
    doc = copy.deepcopy(base)
    fn(doc)
    return rehash(doc) if fix_checksum else doc


def main():
    write('backup/good', 'servo-modbus.json', modbus())
    write('backup/good', 'shuoke.json', shuoke())
    write('backup/good', 'servo-can-empty.json', backup('servo-can', [], address=0, link={'can': 'can0', 'bitrate': 1000000}))

    m, s = modbus(), shuoke()
    text = json.dumps(m, indent=4).encode()
    bad = {
        'malformed--truncated.json': text[:len(text) // 2],
        'malformed--empty.json': b'',
        'malformed--not-an-object.json': b'[1, 2, 3]\n',
        'malformed--deep-nesting.json': b'[' * 5000 + b']' * 5000,
        'malformed--garbage.json': b'\x00\xff\xfe not json at all',
    }
    for name, raw in bad.items():
        write('backup/bad', name, raw=raw)

    def setp(i, k, v):
        return lambda d: d['parameters'][i].__setitem__(k, v)

    cases = {
        'malformed--wrong-format-name.json': (m, lambda d: d.__setitem__('format', 'other-backup'), False),
        'malformed--missing-checksum.json': (m, lambda d: d.pop('checksum'), False),
        'malformed--missing-parameters.json': (m, lambda d: d.pop('parameters'), False),
        'malformed--missing-family.json': (m, lambda d: d.pop('family'), False),
        'malformed--missing-value.json': (m, lambda d: d['parameters'][0].pop('value'), False),
        'malformed--value-is-string.json': (m, setp(0, 'value', '12'), False),
        'malformed--value-fraction.json': (m, setp(0, 'value', 1.5), False),
        'malformed--value-huge.json': (m, setp(0, 'value', 1e300), False),
        'malformed--value-beyond-2p53.json': (m, setp(0, 'value', 9007199254740993), False),
        'malformed--index-is-string.json': (m, setp(0, 'index', '0'), False),
        'malformed--address-is-string.json': (m, lambda d: d.__setitem__('address', '1'), False),
        'malformed--address-out-of-range.json': (m, lambda d: d.__setitem__('address', 300), False),
        'malformed--link-nested.json': (m, lambda d: d['link'].__setitem__('serial', {'baud': 9600}), False),
        'malformed--bad-date.json': (m, lambda d: d.__setitem__('created', 'yesterday'), False),
        'malformed--unknown-field.json': (m, lambda d: d.__setitem__('comment', 'x'), False),
        'malformed--checksum-not-hex.json': (m, lambda d: d.__setitem__('checksum', 'md5:1234'), False),
        'malformed--duplicate-index.json': (m, lambda d: d['parameters'].append(dict(d['parameters'][0])), True),
        'malformed--index-not-in-dictionary.json': (m, lambda d: d['parameters'].append(entry(60, 'PA60', 'x', 0)), True),
        'malformed--key-mismatch.json': (m, setp(0, 'key', 'PA7'), True),
        'malformed--access-mismatch.json': (m, setp(2, 'access', 'rw'), True),
        'malformed--lastwritten-missing.json': (s, lambda d: d['parameters'][3].pop('lastWritten'), True),
        'malformed--lastwritten-on-readable.json': (s, setp(1, 'lastWritten', True), True),
        'checksum--tampered-value.json': (m, setp(0, 'value', 13), False),
        'checksum--wrong-digest.json': (m, lambda d: d.__setitem__('checksum', 'sha256:' + '0' * 64), False),
        'not-supported--format-version-2.json': (m, lambda d: d.__setitem__('formatVersion', 2), False),
        'not-supported--unknown-family.json': (m, lambda d: d.__setitem__('family', 'servo-ethercat'), False),
        'out-of-range--value.json': (m, setp(3, 'value', 300), True),
        'out-of-range--shuoke-speed.json': (s, setp(2, 'value', 100001), True),
    }
    for name, (base, fn, fix) in cases.items():
        write('backup/bad', name, mutate(base, fn, fix))

    # Dictionaries: a small valid one and broken variants.
    def p(i, **kw):
        e = {'index': i, 'key': 'P%d' % i, 'name': {'en': 'Parameter %d' % i, 'zh': '参数 %d' % i},
             'description': {'en': 'Test parameter.', 'zh': '测试参数。'}, 'unit': '',
             'min': -100, 'max': 100, 'access': 'rw'}
        e.update(kw)
        return e
    d = {'format': 'drivedesk-dictionary', 'formatVersion': 1, 'family': 'servo-can', 'valueType': 'int16',
         'parameters': [p(0), p(1, default=5), p(2, access='ro')]}
    write('dictionaries/good', 'servo-can-small.json', d)
    dtext = json.dumps(d, indent=2).encode()
    write('dictionaries/bad', 'malformed--truncated.json', raw=dtext[:-40])
    dcases = {
        'malformed--min-greater-than-max.json': lambda x: x['parameters'][0].update(min=10, max=5),
        'malformed--default-outside-range.json': lambda x: x['parameters'][1].update(default=500),
        'malformed--duplicate-index.json': lambda x: x['parameters'][2].update(index=1, key='P1x'),
        'malformed--duplicate-key.json': lambda x: x['parameters'].append(p(3, key='p1')),
        'malformed--huge-number.json': lambda x: x['parameters'][0].update(max=1e30),
        'malformed--missing-name-zh.json': lambda x: x['parameters'][0]['name'].pop('zh'),
        'malformed--min-is-string.json': lambda x: x['parameters'][0].update(min='0'),
        'malformed--range-beyond-type.json': lambda x: x['parameters'][0].update(max=40000),
        'malformed--bad-access.json': lambda x: x['parameters'][0].update(access='rx'),
        'malformed--key-names-other-index.json': lambda x: x['parameters'][0].update(key='P9'),
        'not-supported--unknown-family.json': lambda x: x.update(family='servo-foo'),
        'not-supported--format-version-9.json': lambda x: x.update(formatVersion=9),
    }
    for name, fn in dcases.items():
        write('dictionaries/bad', name, mutate(d, fn))

    a = {'format': 'drivedesk-alarms', 'formatVersion': 1, 'family': 'servo-can',
         'fallback': {'en': 'Alarm %1', 'zh': '报警 %1'},
         'alarms': [{'code': 0, 'text': {'en': 'No alarm', 'zh': '无报警'}},
                    {'code': 12, 'text': {'en': 'Overcurrent', 'zh': '过流'},
                     'remedy': {'en': 'Check the motor wiring.', 'zh': '检查电机接线。'}}]}
    write('alarms/good', 'servo-can-named.json', a)
    write('alarms/bad', 'malformed--duplicate-code.json', mutate(a, lambda x: x['alarms'].append(copy.deepcopy(x['alarms'][1]))))
    write('alarms/bad', 'malformed--fallback-without-placeholder.json', mutate(a, lambda x: x['fallback'].update(en='Alarm')))
    write('alarms/bad', 'malformed--code-huge.json', mutate(a, lambda x: x['alarms'][1].update(code=1e20)))
    write('alarms/bad', 'malformed--text-missing.json', mutate(a, lambda x: x['alarms'][1].pop('text')))


if __name__ == '__main__':
    main()
