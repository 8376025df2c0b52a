MODULE division_non_integer
  ! Tests: / on num is real division (7 / 2 = 3.5), unlike DIV.
  PROC main()
    TPWrite "7/2=" \Num:=7 / 2;
    TPWrite "7 DIV 2=" \Num:=7 DIV 2;
    TPWrite "1/8=" \Num:=1 / 8;
  ENDPROC
ENDMODULE
