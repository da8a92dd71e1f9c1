//! A solution as an Apache Arrow IPC file (Feather version 2): the schema, one record batch with
//! one non-nullable `Float64` column per series, and the footer, each message's metadata a
//! FlatBuffer. Readable by Polars (`read_ipc`), pyarrow (`pyarrow.ipc.open_file`), pandas
//! (`read_feather`) and DuckDB, without copying: the values sit 8-byte aligned in the file.
//!
//! The FlatBuffers are laid out front to back: a table's vtable just before it, the objects
//! it refers to after it, so every offset points forward as the format requires.

use std::io::{self, Write};

/// Arrow's `MetadataVersion::V5`, `MessageHeader::{Schema, RecordBatch}`, `Type::FloatingPoint`
/// and `Precision::DOUBLE`.
const V5: i16 = 4;
const SCHEMA: u8 = 1;
const RECORD_BATCH: u8 = 3;
const FLOATING_POINT: u8 = 3;
const DOUBLE: i16 = 2;

/// The magic at both ends of an Arrow IPC file.
const MAGIC: &[u8; 6] = b"ARROW1";

/// A FlatBuffer object, to be laid out.
enum Object {
    /// A table: its fields by id.
    Table(Vec<(u16, Field)>),
    /// A string.
    Text(String),
    /// A vector of tables.
    Tables(Vec<Object>),
    /// A vector of `count` structs (their bytes, each a multiple of 8 long), aligned to 8.
    Structs { bytes: Vec<u8>, count: usize },
}

/// A table's field.
enum Field {
    U8(u8),
    I16(i16),
    I64(i64),
    Bool(bool),
    /// An offset to an object laid out after the table.
    Offset(Object),
}

impl Field {
    /// Its size and alignment inside the table.
    fn size(&self) -> usize {
        match self {
            Field::U8(_) | Field::Bool(_) => 1,
            Field::I16(_) => 2,
            Field::Offset(_) => 4,
            Field::I64(_) => 8,
        }
    }
}

/// A FlatBuffer being laid out from its root table.
struct Builder {
    bytes: Vec<u8>,
}

impl Builder {
    /// The bytes of a FlatBuffer whose root is `root`, padded to a multiple of 8.
    fn finish(root: Object) -> Vec<u8> {
        let mut b = Builder { bytes: vec![0; 4] };
        let at = b.place(root);
        b.patch(0, at);
        b.pad(8);
        b.bytes
    }

    fn pad(&mut self, align: usize) {
        while !self.bytes.len().is_multiple_of(align) {
            self.bytes.push(0);
        }
    }

    /// Writes at `field` the offset from it to `target`.
    fn patch(&mut self, field: usize, target: usize) {
        let offset = (target - field) as u32;
        self.bytes[field..field + 4].copy_from_slice(&offset.to_le_bytes());
    }

    /// Lays out `object` at the end (aligned) and returns where it starts.
    fn place(&mut self, object: Object) -> usize {
        match object {
            Object::Table(mut fields) => {
                fields.sort_by_key(|(id, _)| *id);
                let slots = fields.last().map_or(0, |(id, _)| usize::from(*id) + 1);
                // The fields after the table's soffset, largest first so that each is aligned
                // once the table is (to 8).
                let mut order: Vec<usize> = (0..fields.len()).collect();
                order.sort_by_key(|&k| std::cmp::Reverse(fields[k].1.size()));
                let mut at = vec![0usize; fields.len()];
                let mut size: usize = 4;
                for &k in &order {
                    let s = fields[k].1.size();
                    size = size.next_multiple_of(s);
                    at[k] = size;
                    size += s;
                }
                // The vtable, then the table after it at the next 8-aligned position.
                let vtable_len = 4 + 2 * slots;
                self.pad(2);
                let vtable_at = self.bytes.len();
                let mut vtable = vec![0u16; slots];
                for (k, (id, _)) in fields.iter().enumerate() {
                    vtable[usize::from(*id)] = at[k] as u16;
                }
                self.bytes.extend_from_slice(&(vtable_len as u16).to_le_bytes());
                self.bytes.extend_from_slice(&(size as u16).to_le_bytes());
                for slot in vtable {
                    self.bytes.extend_from_slice(&slot.to_le_bytes());
                }
                self.pad(8);
                let table = self.bytes.len();
                self.bytes.extend_from_slice(&((table - vtable_at) as i32).to_le_bytes());
                self.bytes.resize(table + size, 0);
                let mut children = Vec::new();
                for (k, (_, field)) in fields.into_iter().enumerate() {
                    let p = table + at[k];
                    match field {
                        Field::U8(v) => self.bytes[p] = v,
                        Field::Bool(v) => self.bytes[p] = u8::from(v),
                        Field::I16(v) => self.bytes[p..p + 2].copy_from_slice(&v.to_le_bytes()),
                        Field::I64(v) => self.bytes[p..p + 8].copy_from_slice(&v.to_le_bytes()),
                        Field::Offset(child) => children.push((p, child)),
                    }
                }
                for (p, child) in children {
                    let target = self.place(child);
                    self.patch(p, target);
                }
                table
            }
            Object::Text(text) => {
                self.pad(4);
                let at = self.bytes.len();
                self.bytes.extend_from_slice(&(text.len() as u32).to_le_bytes());
                self.bytes.extend_from_slice(text.as_bytes());
                self.bytes.push(0);
                at
            }
            Object::Tables(tables) => {
                self.pad(4);
                let at = self.bytes.len();
                self.bytes.extend_from_slice(&(tables.len() as u32).to_le_bytes());
                let first = self.bytes.len();
                self.bytes.resize(first + 4 * tables.len(), 0);
                for (k, table) in tables.into_iter().enumerate() {
                    let target = self.place(table);
                    self.patch(first + 4 * k, target);
                }
                at
            }
            Object::Structs { bytes, count } => {
                // The length right before elements aligned to 8.
                self.pad(4);
                if self.bytes.len().is_multiple_of(8) {
                    self.bytes.extend_from_slice(&[0; 4]);
                }
                let at = self.bytes.len();
                self.bytes.extend_from_slice(&(count as u32).to_le_bytes());
                self.bytes.extend_from_slice(&bytes);
                at
            }
        }
    }
}

/// The schema: one non-nullable `Float64` field per name.
fn schema(names: &[String]) -> Object {
    let fields = names
        .iter()
        .map(|name| {
            Object::Table(vec![
                (0, Field::Offset(Object::Text(name.clone()))),
                (1, Field::Bool(false)),
                (2, Field::U8(FLOATING_POINT)),
                (3, Field::Offset(Object::Table(vec![(0, Field::I16(DOUBLE))]))),
                (5, Field::Offset(Object::Tables(Vec::new()))),
            ])
        })
        .collect();
    Object::Table(vec![(0, Field::I16(0)), (1, Field::Offset(Object::Tables(fields)))])
}

/// A message around `header`, with a body of `body` bytes.
fn message(kind: u8, header: Object, body: usize) -> Vec<u8> {
    Builder::finish(Object::Table(vec![
        (0, Field::I16(V5)),
        (1, Field::U8(kind)),
        (2, Field::Offset(header)),
        (3, Field::I64(body as i64)),
    ]))
}

/// Writes an encapsulated message: the continuation marker, the metadata's length, the
/// metadata (already padded to 8). Returns the bytes written.
fn encapsulated(out: &mut impl Write, metadata: &[u8]) -> io::Result<usize> {
    out.write_all(&0xFFFF_FFFFu32.to_le_bytes())?;
    out.write_all(&(metadata.len() as i32).to_le_bytes())?;
    out.write_all(metadata)?;
    Ok(8 + metadata.len())
}

/// Writes `columns` (equally long) under `names` as an Arrow IPC file.
pub(crate) fn write(mut out: impl Write, names: &[String], columns: &[&[f64]]) -> io::Result<()> {
    let rows = columns.first().map_or(0, |c| c.len());
    if columns.iter().any(|c| c.len() != rows) || names.len() != columns.len() {
        return Err(io::Error::new(io::ErrorKind::InvalidInput, "columns of different lengths"));
    }
    let size = rows * 8;
    // Each column's values padded to 64 bytes, as Arrow recommends.
    let stride = size.next_multiple_of(64);
    let too_large = || io::Error::new(io::ErrorKind::InvalidInput, "a solution larger than Arrow's offsets");
    let body =
        stride.checked_mul(columns.len()).filter(|&b| i64::try_from(b).is_ok()).ok_or_else(too_large)?;

    out.write_all(MAGIC)?;
    out.write_all(&[0, 0])?;
    let mut position = 8;
    position += encapsulated(&mut out, &message(SCHEMA, schema(names), 0))?;

    // The record batch: per column a node (rows, no nulls) and two buffers (an empty validity
    // bitmap, the values).
    let mut nodes = Vec::with_capacity(16 * columns.len());
    let mut buffers = Vec::with_capacity(32 * columns.len());
    for k in 0..columns.len() {
        nodes.extend_from_slice(&(rows as i64).to_le_bytes());
        nodes.extend_from_slice(&0i64.to_le_bytes());
        let values = (k * stride) as i64;
        for (offset, length) in [(values, 0), (values, size as i64)] {
            buffers.extend_from_slice(&offset.to_le_bytes());
            buffers.extend_from_slice(&length.to_le_bytes());
        }
    }
    let batch = Object::Table(vec![
        (0, Field::I64(rows as i64)),
        (1, Field::Offset(Object::Structs { bytes: nodes, count: columns.len() })),
        (2, Field::Offset(Object::Structs { bytes: buffers, count: 2 * columns.len() })),
    ]);
    let batch_at = position;
    let metadata = message(RECORD_BATCH, batch, body);
    let metadata_len = encapsulated(&mut out, &metadata)?;
    let mut values = Vec::with_capacity(stride);
    for column in columns {
        values.clear();
        for x in column.iter() {
            values.extend_from_slice(&x.to_le_bytes());
        }
        values.resize(stride, 0);
        out.write_all(&values)?;
    }
    // The end of the stream.
    out.write_all(&0xFFFF_FFFFu32.to_le_bytes())?;
    out.write_all(&0i32.to_le_bytes())?;

    // The footer: the schema again and where the record batch is.
    let mut block = Vec::with_capacity(24);
    block.extend_from_slice(&(batch_at as i64).to_le_bytes());
    block.extend_from_slice(&(metadata_len as i32).to_le_bytes());
    block.extend_from_slice(&[0; 4]);
    block.extend_from_slice(&(body as i64).to_le_bytes());
    let footer = Builder::finish(Object::Table(vec![
        (0, Field::I16(V5)),
        (1, Field::Offset(schema(names))),
        (2, Field::Offset(Object::Structs { bytes: Vec::new(), count: 0 })),
        (3, Field::Offset(Object::Structs { bytes: block, count: 1 })),
    ]));
    out.write_all(&footer)?;
    out.write_all(&(footer.len() as i32).to_le_bytes())?;
    out.write_all(MAGIC)?;
    out.flush()
}
