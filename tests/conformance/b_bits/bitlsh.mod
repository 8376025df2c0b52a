MODULE MainModule
  ! Tests: BitLSh shifts left; bits moved past bit 8 are lost (00100110 << 3 = 00110000).
  PROC main()
    VAR byte data1 := 38;
    TPWrite "lsh3=" \Num:=BitLSh(data1, 3);
    TPWrite "one7=" \Num:=BitLSh(1, 7);
    TPWrite "one8=" \Num:=BitLSh(1, 8);
  ENDPROC
ENDMODULE
