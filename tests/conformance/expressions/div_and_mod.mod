MODULE div_and_mod
  ! Tests: DIV is integer division and MOD the remainder for non-negative
  ! integer operands; they bind like * and /.
  PROC main()
    TPWrite "14 DIV 4=" \Num:=14 DIV 4;
    TPWrite "14 MOD 4=" \Num:=14 MOD 4;
    TPWrite "20 DIV 5=" \Num:=20 DIV 5;
    TPWrite "7 MOD 7=" \Num:=7 MOD 7;
    TPWrite "1+7 DIV 2=" \Num:=1 + 7 DIV 2;
    TPWrite "3 MOD 5=" \Num:=3 MOD 5;
  ENDPROC
ENDMODULE
