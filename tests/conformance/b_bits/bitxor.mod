MODULE MainModule
  ! Tests: BitXOr is the bitwise exclusive OR of two bytes (00100111 XOR 10100010 = 10000101).
  PROC main()
    VAR byte data1 := 39;
    VAR byte data2 := 162;
    TPWrite "xor=" \Num:=BitXOr(data1, data2);
    TPWrite "same=" \Num:=BitXOr(255, 255);
    TPWrite "flip=" \Num:=BitXOr(170, 255);
  ENDPROC
ENDMODULE
