#!/usr/bin/env node
// The independent side of airis's MAVLink conformance test (node_conformance_test.cc): node-mavlink
// decodes the frames airis encodes, and encodes the messages airis must decode.
//
//   node node_mavlink_peer.js decode MODULES_DIR < frames.hex > messages.jsonl
//     stdin: hex bytes, any number of lines, read as one byte stream (like a socket). Every byte goes
//     through node-mavlink's own splitter (start byte search, CRC with CRC_EXTRA) and parser. stdout: one
//     JSON object per packet, {"version", "seq", "sysid", "compid", "msgid", "payload_length", "signed",
//     "fields": {...}}, then {"summary": {"valid", "invalid", "unknown"}} from the splitter's counters.
//   node node_mavlink_peer.js encode MODULES_DIR < messages.jsonl > frames.hex
//     stdin: one JSON object per line, {"version": 1|2, "signed": bool, "seq", "sysid", "compid",
//     "msgid", "fields": {...}}; stdout: one frame per line as hex, from node-mavlink's serializer (and
//     its signer for "signed").
//
// MODULES_DIR is the node_modules folder that scripts/install-node-deps.sh filled.
// Field values in JSON, keyed by the field names of common.xml: 8- to 32-bit integers as numbers, 64-bit
// integers as decimal strings, float as its IEEE-754 bit pattern (a number) and double as its bit
// pattern (a decimal string), so that comparisons are bit-exact; char[N] as a string; arrays as arrays.
'use strict';

const path = require('path');

const [mode, modulesDir] = process.argv.slice(2);
if (!['decode', 'encode'].includes(mode) || !modulesDir) {
  process.stderr.write('usage: node_mavlink_peer.js decode|encode NODE_MODULES_DIR\n');
  process.exit(2);
}
const nm = require(require.resolve('node-mavlink', { paths: [path.resolve(modulesDir)] }));
const REGISTRY = { ...nm.minimal.REGISTRY, ...nm.common.REGISTRY };

const f32 = new Float32Array(1);
const u32 = new Uint32Array(f32.buffer);
const f64 = new Float64Array(1);
const u64 = new BigUint64Array(f64.buffer);

function scalarToJson(type, v) {
  switch (type) {
    case 'float': f32[0] = v; return u32[0];
    case 'double': f64[0] = v; return u64[0].toString();
    case 'int64_t': case 'uint64_t': return v.toString();
    default: return v;  // integers (uint8_t_mavlink_version included)
  }
}

function scalarFromJson(type, v) {
  switch (type) {
    case 'float': u32[0] = v; return f32[0];
    case 'double': u64[0] = BigInt(v); return f64[0];
    case 'int64_t': case 'uint64_t': return BigInt(v);
    default: return v;
  }
}

function fieldToJson(field, value) {
  if (field.type === 'char[]') return value;
  if (field.type.endsWith('[]')) return value.map((e) => scalarToJson(field.type.slice(0, -2), e));
  return scalarToJson(field.type, value);
}

function fieldFromJson(field, value) {
  if (field.type === 'char[]') return value;
  if (field.type.endsWith('[]')) return value.map((e) => scalarFromJson(field.type.slice(0, -2), e));
  return scalarFromJson(field.type, value);
}

function readStdin() {
  return require('fs').readFileSync(0, 'utf8');
}

function decode() {
  const splitter = new nm.MavLinkPacketSplitter();
  const parser = new nm.MavLinkPacketParser();
  const out = [];
  parser.on('data', (packet) => {
    const clazz = REGISTRY[packet.header.msgid];
    const data = packet.protocol.data(packet.payload, clazz);
    const fields = {};
    for (const field of clazz.FIELDS) fields[field.source] = fieldToJson(field, data[field.name]);
    out.push(JSON.stringify({
      version: packet.protocol instanceof nm.MavLinkProtocolV2 ? 2 : 1,
      seq: packet.header.seq,
      sysid: packet.header.sysid,
      compid: packet.header.compid,
      msgid: packet.header.msgid,
      payload_length: packet.header.payloadLength,
      signed: packet.signature !== null,
      fields,
    }));
  });
  parser.on('end', () => {
    out.push(JSON.stringify({
      summary: {
        valid: splitter.validPackages,
        invalid: splitter.invalidPackages,
        unknown: splitter.unknownPackagesCount,
      },
    }));
    process.stdout.write(out.join('\n') + '\n');
  });
  splitter.pipe(parser);
  splitter.end(Buffer.from(readStdin().replace(/\s+/g, ''), 'hex'));
}

function encode() {
  const key = nm.MavLinkPacketSignature.key('airis conformance');
  const lines = readStdin().split('\n').filter((l) => l.trim() !== '');
  const out = lines.map((line) => {
    const req = JSON.parse(line);
    const clazz = REGISTRY[req.msgid];
    if (!clazz) throw new Error(`node-mavlink knows no message ${req.msgid}`);
    const msg = new clazz();
    const names = new Set(clazz.FIELDS.map((f) => f.source));
    for (const name of Object.keys(req.fields)) {
      if (!names.has(name)) throw new Error(`${clazz.MSG_NAME} has no field ${name}`);
    }
    for (const field of clazz.FIELDS) {
      if (!(field.source in req.fields)) throw new Error(`${clazz.MSG_NAME}.${field.source} missing`);
      msg[field.name] = fieldFromJson(field, req.fields[field.source]);
    }
    if (req.version === 1) return new nm.MavLinkProtocolV1(req.sysid, req.compid).serialize(msg, req.seq);
    const flags = req.signed ? nm.MavLinkProtocolV2.IFLAG_SIGNED : 0;
    const protocol = new nm.MavLinkProtocolV2(req.sysid, req.compid, flags);
    const frame = protocol.serialize(msg, req.seq);
    // A fixed signing time keeps the output reproducible.
    return req.signed ? protocol.sign(frame, 1, key, Date.UTC(2026, 0, 1)) : frame;
  });
  process.stdout.write(out.map((b) => b.toString('hex')).join('\n') + '\n');
}

if (mode === 'decode') decode(); else encode();
