MODULE long_jump_retry_loop
  ! Tests: RETRY in an ERROR (LONG_JMP_ALL_ERR) recovery point re-executes
  ! the call statement of that routine (the pattern real controller code uses
  ! to restart a service loop after an error deep inside it).
  VAR num rounds := 0;
  PROC serve()
    rounds := rounds + 1;
    TPWrite "round " \Num:=rounds;
    IF rounds < 3 RAISE 20;
  ENDPROC
  PROC loop()
    serve;
  ENDPROC
  PROC main()
    loop;
    TPWrite "served";
  ERROR (LONG_JMP_ALL_ERR)
    RETRY;
  ENDPROC
ENDMODULE
