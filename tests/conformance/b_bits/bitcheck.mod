MODULE MainModule
  ! Tests: BitCheck numbers bits 1 (least significant) to 8: 130 = 10000010 has bits 8 and 2 set.
  PROC main()
    VAR byte data1 := 130;
    TPWrite "bit8=" \Bool:=BitCheck(data1, 8);
    TPWrite "bit2=" \Bool:=BitCheck(data1, 2);
    TPWrite "bit1=" \Bool:=BitCheck(data1, 1);
    TPWrite "bit7=" \Bool:=BitCheck(data1, 7);
  ENDPROC
ENDMODULE
