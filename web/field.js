// Field records of trace format 2 (spec/exploration/trace_field.hpp): float32 little endian and
// a bitset, both base64.

export function base64Bytes(text) {
  const bin = atob(text);
  const out = new Uint8Array(bin.length);
  for (let k = 0; k < bin.length; ++k) out[k] = bin.charCodeAt(k);
  return out;
}

// {step, n, pheromone: Float32Array (i*n + j), visited: Uint8Array of 0/1, max, digest}
export function decodeField(record, n) {
  const bytes = base64Bytes(record.pheromone);
  const view = new DataView(bytes.buffer);
  const pheromone = new Float32Array(n * n);
  for (let k = 0; k < n * n; ++k) pheromone[k] = view.getFloat32(4 * k, true);
  const bits = base64Bytes(record.visited);
  const visited = new Uint8Array(n * n);
  for (let k = 0; k < n * n; ++k) visited[k] = (bits[k >> 3] >> (k & 7)) & 1;
  return { step: record.step, n, pheromone, visited, max: record.pheromone_max, digest: record.digest };
}

// The field shown at a step: the last record at or before it (records sorted by step).
export function fieldAt(fields, step) {
  let lo = 0, hi = fields.length - 1, best = -1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (fields[mid].step <= step) { best = mid; lo = mid + 1; } else hi = mid - 1;
  }
  return best;
}
