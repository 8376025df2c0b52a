MODULE array_dimension_constant
  ! Tests: an array dimension may be a named CONST (also a CONST expression);
  ! Dim returns the declared size.
  CONST num N := 4;
  VAR num a{N};
  VAR string names{N + 1};
  PROC main()
    TPWrite "dim a=" \Num:=Dim(a, 1);
    TPWrite "dim names=" \Num:=Dim(names, 1);
    TPWrite "[" + names{5} + "]";
  ENDPROC
ENDMODULE
