MODULE string_concat_chain
  ! Tests: + on strings is left-associative concatenation of several operands,
  ! including string variables, record components and array elements.
  RECORD tag
    string text;
  ENDRECORD
  PROC main()
    VAR string parts{2} := ["x", "y"];
    VAR tag t := ["z"];
    TPWrite parts{1} + "-" + parts{2} + "-" + t.text;
    TPWrite "[" + "" + "" + "]";
    TPWrite "end";
  ENDPROC
ENDMODULE
