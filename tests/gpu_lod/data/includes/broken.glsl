// Included by include_error.tesc: uses a name nobody declares.
float factor() {
  return uUndeclared * 2.0;
}
