MODULE MainModule
  ! Tests: BitClear clears one bit of a byte variable; clearing a clear bit changes nothing.
  PROC main()
    VAR byte data1 := 130;
    BitClear data1, 2;
    TPWrite "clear2=" \Num:=data1;
    BitClear data1, 1;
    TPWrite "clear1=" \Num:=data1;
    BitClear data1, 8;
    TPWrite "clear8=" \Num:=data1;
  ENDPROC
ENDMODULE
