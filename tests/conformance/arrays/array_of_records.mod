MODULE array_of_records
  ! Tests: an array of records: components of an element are assigned with
  ! a{i}.c and elements default to the record default.
  VAR pos pts{3};
  PROC main()
    pts{2}.y := 4;
    pts{3} := [7, 8, 9];
    TPWrite "p1=" \Pos:=pts{1};
    TPWrite "p2=" \Pos:=pts{2};
    TPWrite "p3=" \Pos:=pts{3};
  ENDPROC
ENDMODULE
