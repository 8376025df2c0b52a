MODULE MainModule
  ! Tests: BitRSh shifts right; bits moved past bit 1 are lost (00100110 >> 3 = 00000100).
  PROC main()
    VAR byte data1 := 38;
    TPWrite "rsh3=" \Num:=BitRSh(data1, 3);
    TPWrite "top7=" \Num:=BitRSh(128, 7);
    TPWrite "all8=" \Num:=BitRSh(255, 8);
  ENDPROC
ENDMODULE
