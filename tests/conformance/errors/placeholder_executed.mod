MODULE placeholder_executed
  ! Tests: editor placeholders (<SMT>, <EXP>, <VAR>) load; executing one raises ERR_EXECPHR,
  ! which an ERROR handler can take (RAPID kernel reference, "Placeholders": a program with
  ! placeholders can be loaded and even executed, but any placeholder encountered causes an
  ! execution error). A placeholder that is never reached changes nothing.
  VAR num x := 0;
  VAR num caught := 0;
  PROC main()
    IF x = 1 THEN
      <SMT>
      MoveJ <EXP>, v1000, z50, tool0;
    ENDIF
    unfinished;
    TPWrite "caught " \Num:=caught;
    x := <EXP> + 1;
    TPWrite "not reached";
  ENDPROC
  PROC unfinished()
    <SMT>
    <VAR> := 3;
    Incr <VAR>;
  ERROR
    IF ERRNO = ERR_EXECPHR THEN
      caught := caught + 1;
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
