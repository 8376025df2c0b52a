MODULE MainModule
  ! Tests: BitNeg is the one's complement within 8 bits (NOT 00100110 = 11011001).
  PROC main()
    VAR byte data1 := 38;
    TPWrite "neg=" \Num:=BitNeg(data1);
    TPWrite "zero=" \Num:=BitNeg(0);
    TPWrite "full=" \Num:=BitNeg(255);
  ENDPROC
ENDMODULE
