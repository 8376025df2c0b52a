MODULE MainModule
  ! Tests: StrDigCalc does integer arithmetic on digit strings with OpAdd, OpSub, OpMult,
  ! OpDiv (integer division) and OpMod.
  PROC main()
    TPWrite "add=" + StrDigCalc("31", OpAdd, "11");
    TPWrite "sub=" + StrDigCalc("31", OpSub, "11");
    TPWrite "mult=" + StrDigCalc("7", OpMult, "6");
    TPWrite "div=" + StrDigCalc("7", OpDiv, "2");
    TPWrite "mod=" + StrDigCalc("7", OpMod, "2");
    TPWrite "big=" + StrDigCalc("4294967294", OpAdd, "1");
  ENDPROC
ENDMODULE
