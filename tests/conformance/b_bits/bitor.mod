MODULE MainModule
  ! Tests: BitOr is the bitwise OR of two bytes (00100111 OR 10100010 = 10100111).
  PROC main()
    VAR byte data1 := 39;
    VAR byte data2 := 162;
    TPWrite "or=" \Num:=BitOr(data1, data2);
    TPWrite "zero=" \Num:=BitOr(0, 0);
    TPWrite "halves=" \Num:=BitOr(240, 15);
  ENDPROC
ENDMODULE
