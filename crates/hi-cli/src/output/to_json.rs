// SPDX-License-Identifier: MIT
//! A `serde` serializer whose output is a [`Json`] tree, so that every report `hi` prints goes
//! through the `Serialize` derives of its types (the library's reports and the command's own
//! output structs) while keeping the printing rules of [`super`]: keys in declaration order,
//! and non-finite numbers kept (they are printed as strings, never silently as `null`).
//!
//! The mapping is serde's data model as `serde_json` writes it: unit and `None` are `null`; a
//! newtype is its content; a unit variant is its name; a newtype, tuple or struct variant is an
//! object with one key, the variant's name; sequences, tuples and tuple structs are arrays;
//! maps and structs are objects (map keys must be strings, numbers or booleans).

use std::fmt::Display;

use serde::ser::{self, Impossible, Serialize};

use super::Json;

/// The [`Json`] tree of `value`.
///
/// # Errors
///
/// A map with a key that is not a string, number or boolean, or a custom error raised by a
/// `Serialize` implementation.
pub(crate) fn to_json<T: Serialize + ?Sized>(value: &T) -> Result<Json, Error> {
    value.serialize(JsonSerializer)
}

/// Why a value has no JSON form.
#[derive(Debug)]
pub(crate) struct Error(String);

impl Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Error {}

impl ser::Error for Error {
    fn custom<T: Display>(msg: T) -> Self {
        Error(msg.to_string())
    }
}

struct JsonSerializer;

/// An array being built (a sequence, tuple or tuple struct), or the fields of a tuple variant.
struct ArrayBuilder {
    items: Vec<Json>,
    variant: Option<&'static str>,
}

/// An object being built (a map or struct), or the fields of a struct variant.
struct ObjectBuilder {
    fields: Vec<(String, Json)>,
    next_key: Option<String>,
    variant: Option<&'static str>,
}

fn wrap(variant: Option<&'static str>, value: Json) -> Json {
    match variant {
        Some(name) => Json::Object(vec![(name.to_owned(), value)]),
        None => value,
    }
}

impl ser::Serializer for JsonSerializer {
    type Ok = Json;
    type Error = Error;
    type SerializeSeq = ArrayBuilder;
    type SerializeTuple = ArrayBuilder;
    type SerializeTupleStruct = ArrayBuilder;
    type SerializeTupleVariant = ArrayBuilder;
    type SerializeMap = ObjectBuilder;
    type SerializeStruct = ObjectBuilder;
    type SerializeStructVariant = ObjectBuilder;

    fn serialize_bool(self, v: bool) -> Result<Json, Error> {
        Ok(Json::Bool(v))
    }
    fn serialize_i8(self, v: i8) -> Result<Json, Error> {
        self.serialize_i64(i64::from(v))
    }
    fn serialize_i16(self, v: i16) -> Result<Json, Error> {
        self.serialize_i64(i64::from(v))
    }
    fn serialize_i32(self, v: i32) -> Result<Json, Error> {
        self.serialize_i64(i64::from(v))
    }
    fn serialize_i64(self, v: i64) -> Result<Json, Error> {
        Ok(Json::Integer(v.into()))
    }
    fn serialize_u8(self, v: u8) -> Result<Json, Error> {
        self.serialize_u64(u64::from(v))
    }
    fn serialize_u16(self, v: u16) -> Result<Json, Error> {
        self.serialize_u64(u64::from(v))
    }
    fn serialize_u32(self, v: u32) -> Result<Json, Error> {
        self.serialize_u64(u64::from(v))
    }
    fn serialize_u64(self, v: u64) -> Result<Json, Error> {
        Ok(Json::Integer(v.into()))
    }
    fn serialize_f32(self, v: f32) -> Result<Json, Error> {
        // Through the shortest decimal of the f32, so that 0.1f32 prints as 0.1.
        let wide = if v.is_finite() { v.to_string().parse().ok() } else { None };
        Ok(Json::Number(wide.unwrap_or(f64::from(v))))
    }
    fn serialize_f64(self, v: f64) -> Result<Json, Error> {
        Ok(Json::Number(v))
    }
    fn serialize_char(self, v: char) -> Result<Json, Error> {
        Ok(Json::String(v.to_string()))
    }
    fn serialize_str(self, v: &str) -> Result<Json, Error> {
        Ok(Json::String(v.to_owned()))
    }
    fn serialize_bytes(self, v: &[u8]) -> Result<Json, Error> {
        Ok(Json::Array(v.iter().map(|&b| Json::Integer(b.into())).collect()))
    }
    fn serialize_none(self) -> Result<Json, Error> {
        Ok(Json::Null)
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<Json, Error> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<Json, Error> {
        Ok(Json::Null)
    }
    fn serialize_unit_struct(self, _name: &'static str) -> Result<Json, Error> {
        Ok(Json::Null)
    }
    fn serialize_unit_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
    ) -> Result<Json, Error> {
        Ok(Json::String(variant.to_owned()))
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _name: &'static str,
        value: &T,
    ) -> Result<Json, Error> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<Json, Error> {
        Ok(wrap(Some(variant), value.serialize(self)?))
    }
    fn serialize_seq(self, len: Option<usize>) -> Result<ArrayBuilder, Error> {
        Ok(ArrayBuilder { items: Vec::with_capacity(len.unwrap_or(0)), variant: None })
    }
    fn serialize_tuple(self, len: usize) -> Result<ArrayBuilder, Error> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_struct(
        self,
        _name: &'static str,
        len: usize,
    ) -> Result<ArrayBuilder, Error> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<ArrayBuilder, Error> {
        Ok(ArrayBuilder { items: Vec::with_capacity(len), variant: Some(variant) })
    }
    fn serialize_map(self, len: Option<usize>) -> Result<ObjectBuilder, Error> {
        Ok(ObjectBuilder {
            fields: Vec::with_capacity(len.unwrap_or(0)),
            next_key: None,
            variant: None,
        })
    }
    fn serialize_struct(self, _name: &'static str, len: usize) -> Result<ObjectBuilder, Error> {
        self.serialize_map(Some(len))
    }
    fn serialize_struct_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<ObjectBuilder, Error> {
        Ok(ObjectBuilder {
            fields: Vec::with_capacity(len),
            next_key: None,
            variant: Some(variant),
        })
    }
}

impl ser::SerializeSeq for ArrayBuilder {
    type Ok = Json;
    type Error = Error;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Error> {
        self.items.push(value.serialize(JsonSerializer)?);
        Ok(())
    }
    fn end(self) -> Result<Json, Error> {
        Ok(wrap(self.variant, Json::Array(self.items)))
    }
}

impl ser::SerializeTuple for ArrayBuilder {
    type Ok = Json;
    type Error = Error;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Error> {
        ser::SerializeSeq::serialize_element(self, value)
    }
    fn end(self) -> Result<Json, Error> {
        ser::SerializeSeq::end(self)
    }
}

impl ser::SerializeTupleStruct for ArrayBuilder {
    type Ok = Json;
    type Error = Error;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Error> {
        ser::SerializeSeq::serialize_element(self, value)
    }
    fn end(self) -> Result<Json, Error> {
        ser::SerializeSeq::end(self)
    }
}

impl ser::SerializeTupleVariant for ArrayBuilder {
    type Ok = Json;
    type Error = Error;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Error> {
        ser::SerializeSeq::serialize_element(self, value)
    }
    fn end(self) -> Result<Json, Error> {
        ser::SerializeSeq::end(self)
    }
}

impl ser::SerializeMap for ObjectBuilder {
    type Ok = Json;
    type Error = Error;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Error> {
        self.next_key = Some(key.serialize(KeySerializer)?);
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Error> {
        let key =
            self.next_key.take().ok_or_else(|| Error("a map value without its key".into()))?;
        self.fields.push((key, value.serialize(JsonSerializer)?));
        Ok(())
    }
    fn end(self) -> Result<Json, Error> {
        Ok(wrap(self.variant, Json::Object(self.fields)))
    }
}

impl ser::SerializeStruct for ObjectBuilder {
    type Ok = Json;
    type Error = Error;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Error> {
        self.fields.push((key.to_owned(), value.serialize(JsonSerializer)?));
        Ok(())
    }
    fn end(self) -> Result<Json, Error> {
        ser::SerializeMap::end(self)
    }
}

impl ser::SerializeStructVariant for ObjectBuilder {
    type Ok = Json;
    type Error = Error;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Error> {
        ser::SerializeStruct::serialize_field(self, key, value)
    }
    fn end(self) -> Result<Json, Error> {
        ser::SerializeMap::end(self)
    }
}

/// Map keys: strings, and numbers or booleans written as strings (as `serde_json` does).
struct KeySerializer;

fn key_error() -> Error {
    Error("a map key must be a string, a number or a boolean".into())
}

/// `fn $name(self, v: $ty) -> Result<String, Error> { Ok(v.to_string()) }` for each type.
macro_rules! key_to_string {
    ($($name:ident: $ty:ty),*) => {
        $(fn $name(self, v: $ty) -> Result<String, Error> {
            Ok(v.to_string())
        })*
    };
}

impl ser::Serializer for KeySerializer {
    type Ok = String;
    type Error = Error;
    type SerializeSeq = Impossible<String, Error>;
    type SerializeTuple = Impossible<String, Error>;
    type SerializeTupleStruct = Impossible<String, Error>;
    type SerializeTupleVariant = Impossible<String, Error>;
    type SerializeMap = Impossible<String, Error>;
    type SerializeStruct = Impossible<String, Error>;
    type SerializeStructVariant = Impossible<String, Error>;

    key_to_string!(
        serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_f32: f32, serialize_f64: f64, serialize_char: char,
        serialize_str: &str
    );

    fn serialize_bytes(self, _v: &[u8]) -> Result<String, Error> {
        Err(key_error())
    }
    fn serialize_none(self) -> Result<String, Error> {
        Err(key_error())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<String, Error> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<String, Error> {
        Err(key_error())
    }
    fn serialize_unit_struct(self, _name: &'static str) -> Result<String, Error> {
        Err(key_error())
    }
    fn serialize_unit_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
    ) -> Result<String, Error> {
        Ok(variant.to_owned())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _name: &'static str,
        value: &T,
    ) -> Result<String, Error> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _name: &'static str,
        _index: u32,
        _variant: &'static str,
        _value: &T,
    ) -> Result<String, Error> {
        Err(key_error())
    }
    fn serialize_seq(self, _len: Option<usize>) -> Result<Self::SerializeSeq, Error> {
        Err(key_error())
    }
    fn serialize_tuple(self, _len: usize) -> Result<Self::SerializeTuple, Error> {
        Err(key_error())
    }
    fn serialize_tuple_struct(
        self,
        _name: &'static str,
        _len: usize,
    ) -> Result<Self::SerializeTupleStruct, Error> {
        Err(key_error())
    }
    fn serialize_tuple_variant(
        self,
        _name: &'static str,
        _index: u32,
        _variant: &'static str,
        _len: usize,
    ) -> Result<Self::SerializeTupleVariant, Error> {
        Err(key_error())
    }
    fn serialize_map(self, _len: Option<usize>) -> Result<Self::SerializeMap, Error> {
        Err(key_error())
    }
    fn serialize_struct(
        self,
        _name: &'static str,
        _len: usize,
    ) -> Result<Self::SerializeStruct, Error> {
        Err(key_error())
    }
    fn serialize_struct_variant(
        self,
        _name: &'static str,
        _index: u32,
        _variant: &'static str,
        _len: usize,
    ) -> Result<Self::SerializeStructVariant, Error> {
        Err(key_error())
    }
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use serde::Serialize;

    use super::*;

    #[derive(Serialize)]
    #[serde(rename_all = "snake_case")]
    enum Shape {
        Unit,
        Newtype(f64),
        Tuple(u8, i8),
        Struct { side: f32 },
    }

    #[derive(Serialize)]
    struct Report {
        b: Vec<Shape>,
        a: Option<f64>,
        counts: (usize, i64),
        keys: BTreeMap<u32, bool>,
        infinite: f64,
    }

    #[test]
    fn the_data_model_maps_to_json_as_serde_json_writes_it() {
        let report = Report {
            b: vec![
                Shape::Unit,
                Shape::Newtype(0.5),
                Shape::Tuple(1, -2),
                Shape::Struct { side: 0.25 },
            ],
            a: None,
            counts: (3, -4),
            keys: BTreeMap::from([(7, true)]),
            infinite: f64::NEG_INFINITY,
        };
        let mut ours = Vec::new();
        super::super::write_json(&mut ours, &to_json(&report).unwrap(), false).unwrap();
        let ours = String::from_utf8(ours).unwrap();
        assert_eq!(
            ours,
            "{\"b\":[\"unit\",{\"newtype\":0.5},{\"tuple\":[1,-2]},{\"struct\":{\"side\":0.25}}],\"a\":null,\"counts\":[3,-4],\"keys\":{\"7\":true},\"infinite\":\"-Infinity\"}\n"
        );
        // serde_json writes the same text, except that it turns −∞ into null.
        let theirs = serde_json::to_string(&report).unwrap();
        assert_eq!(ours.trim_end().replace("\"-Infinity\"", "null"), theirs);
    }

    #[test]
    fn a_map_keyed_by_a_sequence_is_an_error() {
        let map = BTreeMap::from([(vec![1u8], 1.0)]);
        assert!(to_json(&map).is_err());
    }
}
