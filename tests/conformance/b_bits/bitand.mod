MODULE MainModule
  ! Tests: BitAnd is the bitwise AND of two bytes (manual example 38 AND 34 = 34).
  PROC main()
    VAR byte data1 := 38;
    VAR byte data2 := 34;
    TPWrite "and=" \Num:=BitAnd(data1, data2);
    TPWrite "mask=" \Num:=BitAnd(255, 15);
    TPWrite "disjoint=" \Num:=BitAnd(170, 85);
  ENDPROC
ENDMODULE
