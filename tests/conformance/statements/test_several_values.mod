MODULE test_several_values
  ! Tests: TEST compares with each CASE value in order; a CASE may list
  ! several values; DEFAULT runs when no value matches; no fall-through.
  PROC kind(num v)
    TEST v
    CASE 1, 2, 3:
      TPWrite "low " \Num:=v;
    CASE 4:
      TPWrite "four";
    DEFAULT:
      TPWrite "other " \Num:=v;
    ENDTEST
  ENDPROC
  PROC main()
    kind 2;
    kind 4;
    kind 3;
    kind 9;
  ENDPROC
ENDMODULE
