MODULE pers_negative_literal
  ! Tests: a PERS initialiser is a literal expression, where unary minus is
  ! allowed (also inside aggregates).
  PERS num offset := -5;
  PERS pos home := [-1, 0, 2.5];
  PROC main()
    TPWrite "offset=" \Num:=offset;
    TPWrite "home=" \Pos:=home;
  ENDPROC
ENDMODULE
