MODULE MainModule
  ! Tests: BitSet sets one bit of a byte variable; setting a bit that is already set changes nothing.
  PROC main()
    VAR byte data1 := 2;
    BitSet data1, 8;
    TPWrite "set8=" \Num:=data1;
    BitSet data1, 2;
    TPWrite "set2=" \Num:=data1;
    BitSet data1, 1;
    TPWrite "set1=" \Num:=data1;
  ENDPROC
ENDMODULE
