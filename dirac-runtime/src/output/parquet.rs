//! A solution as an Apache Parquet file: one row group, one required `DOUBLE` column per
//! series, each in one uncompressed data page of plain-encoded values, and the file's metadata
//! in Thrift's compact protocol. Readable by Polars, pandas (pyarrow), DuckDB and Spark.

use std::io::{self, Write};

/// Thrift compact protocol's field types.
const I32: u8 = 5;
const I64: u8 = 6;
const BINARY: u8 = 8;
const LIST: u8 = 9;
const STRUCT: u8 = 12;

/// Parquet's physical type `DOUBLE`, repetition `REQUIRED`, encodings `PLAIN` and `RLE`, codec
/// `UNCOMPRESSED` and page type `DATA_PAGE`.
const DOUBLE: i64 = 5;
const REQUIRED: i64 = 0;
const PLAIN: i64 = 0;
const RLE: i64 = 3;
const UNCOMPRESSED: i64 = 0;
const DATA_PAGE: i64 = 0;

/// A Thrift struct being written in the compact protocol.
struct Thrift {
    bytes: Vec<u8>,
    /// The last field id of each open struct.
    last: Vec<i16>,
}

impl Thrift {
    fn new() -> Self {
        Thrift { bytes: Vec::new(), last: vec![0] }
    }

    fn varint(&mut self, mut value: u64) {
        loop {
            let byte = (value & 0x7f) as u8;
            value >>= 7;
            if value == 0 {
                self.bytes.push(byte);
                return;
            }
            self.bytes.push(byte | 0x80);
        }
    }

    fn zigzag(&mut self, value: i64) {
        self.varint(((value << 1) ^ (value >> 63)) as u64);
    }

    fn field(&mut self, id: i16, kind: u8) {
        // The top-level struct is open from `new` on, so there is always a last id.
        let last = self.last.last().copied().unwrap_or(0);
        let delta = id - last;
        if (1..=15).contains(&delta) {
            self.bytes.push(((delta as u8) << 4) | kind);
        } else {
            self.bytes.push(kind);
            self.zigzag(i64::from(id));
        }
        if let Some(last) = self.last.last_mut() {
            *last = id;
        }
    }

    fn int(&mut self, id: i16, kind: u8, value: i64) {
        self.field(id, kind);
        self.zigzag(value);
    }

    fn string(&mut self, id: i16, text: &str) {
        self.field(id, BINARY);
        self.varint(text.len() as u64);
        self.bytes.extend_from_slice(text.as_bytes());
    }

    fn list_header(&mut self, id: i16, kind: u8, len: usize) {
        self.field(id, LIST);
        if len < 15 {
            self.bytes.push(((len as u8) << 4) | kind);
        } else {
            self.bytes.push(0xf0 | kind);
            self.varint(len as u64);
        }
    }

    /// Opens a struct as field `id` (or as a list's element, for `None`).
    fn open(&mut self, id: Option<i16>) {
        if let Some(id) = id {
            self.field(id, STRUCT);
        }
        self.last.push(0);
    }

    fn close(&mut self) {
        self.bytes.push(0);
        self.last.pop();
    }
}

/// Writes the columns `columns`, named `names`, all of the same length, as a Parquet file.
pub(crate) fn write(mut out: impl Write, names: &[String], columns: &[&[f64]]) -> io::Result<()> {
    let rows = columns.first().map_or(0, |c| c.len());
    if columns.iter().any(|c| c.len() != rows) || names.len() != columns.len() {
        return Err(io::Error::new(io::ErrorKind::InvalidInput, "columns of different lengths"));
    }
    let size = rows * 8;
    let too_large =
        || io::Error::new(io::ErrorKind::InvalidInput, "a column larger than a Parquet page holds");
    let page_size = i64::try_from(size).ok().filter(|&s| s <= i64::from(i32::MAX)).ok_or_else(too_large)?;
    out.write_all(b"PAR1")?;
    let mut offset = 4i64;
    // Each column's chunk: its page header, then its values; where it starts and its size.
    let mut chunks = Vec::with_capacity(columns.len());
    let mut values = Vec::with_capacity(size);
    for column in columns {
        let mut header = Thrift::new();
        header.int(1, I32, DATA_PAGE);
        header.int(2, I32, page_size);
        header.int(3, I32, page_size);
        header.open(Some(5));
        header.int(1, I32, rows as i64);
        header.int(2, I32, PLAIN);
        header.int(3, I32, RLE);
        header.int(4, I32, RLE);
        header.close();
        header.bytes.push(0);
        values.clear();
        for x in column.iter() {
            values.extend_from_slice(&x.to_le_bytes());
        }
        out.write_all(&header.bytes)?;
        out.write_all(&values)?;
        let chunk = (header.bytes.len() + size) as i64;
        chunks.push((offset, chunk));
        offset += chunk;
    }
    let mut meta = Thrift::new();
    meta.int(1, I32, 1);
    meta.list_header(2, STRUCT, names.len() + 1);
    meta.open(None);
    meta.string(4, "schema");
    meta.int(5, I32, names.len() as i64);
    meta.close();
    for name in names {
        meta.open(None);
        meta.int(1, I32, DOUBLE);
        meta.int(3, I32, REQUIRED);
        meta.string(4, name);
        meta.close();
    }
    meta.int(3, I64, rows as i64);
    meta.list_header(4, STRUCT, 1);
    meta.open(None);
    meta.list_header(1, STRUCT, columns.len());
    for (name, &(start, length)) in names.iter().zip(&chunks) {
        meta.open(None);
        meta.int(2, I64, start);
        meta.open(Some(3));
        meta.int(1, I32, DOUBLE);
        meta.list_header(2, I32, 2);
        meta.zigzag(PLAIN);
        meta.zigzag(RLE);
        meta.list_header(3, BINARY, 1);
        meta.varint(name.len() as u64);
        meta.bytes.extend_from_slice(name.as_bytes());
        meta.int(4, I32, UNCOMPRESSED);
        meta.int(5, I64, rows as i64);
        meta.int(6, I64, length);
        meta.int(7, I64, length);
        meta.int(9, I64, start);
        meta.close();
        meta.close();
    }
    meta.int(2, I64, chunks.iter().map(|c| c.1).sum());
    meta.int(3, I64, rows as i64);
    meta.close();
    meta.string(6, concat!("dirac version ", env!("CARGO_PKG_VERSION")));
    meta.bytes.push(0);
    out.write_all(&meta.bytes)?;
    out.write_all(&(meta.bytes.len() as u32).to_le_bytes())?;
    out.write_all(b"PAR1")?;
    out.flush()
}
