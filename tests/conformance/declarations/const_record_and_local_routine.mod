MODULE const_record_and_local_routine
  ! Tests: a CONST record initialised by an aggregate; a LOCAL PROC and a
  ! LOCAL FUNC are callable from their own module.
  CONST pos ORIGIN := [1, 2, 3];
  LOCAL FUNC num twice(num v)
    RETURN 2 * v;
  ENDFUNC
  LOCAL PROC show(pos p)
    TPWrite "p=" \Pos:=p;
  ENDPROC
  PROC main()
    show ORIGIN;
    TPWrite "2y=" \Num:=twice(ORIGIN.y);
  ENDPROC
ENDMODULE
