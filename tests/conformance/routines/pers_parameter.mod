MODULE pers_parameter
  ! Tests: a PERS parameter takes a persistent by reference; the change is
  ! visible through the persistent's own name.
  PERS num level := 1;
  PERS string tag := "a";
  PROC lift(PERS num v, PERS string s)
    v := v + 10;
    s := s + "b";
  ENDPROC
  PROC main()
    lift level, tag;
    TPWrite tag \Num:=level;
  ENDPROC
ENDMODULE
