MODULE Server
  ! A command server whose CASEs each count with their own FOR i, beside routine data i:
  ! the counterexample names the counter of the loop the run is in.
  VAR num count := 0;
  VAR num targets{4} := [10,20,30,40];
  VAR num command := 0;
  VAR num moved := 0;
  PROC main()
    WHILE command < 3 DO
      Serve;
    ENDWHILE
  ENDPROC

  PROC Serve()
    VAR num i := 7;
    command := command + 1;
    TEST command
    CASE 1:
      FOR i FROM 1 TO 4 DO
        moved := targets{i};
      ENDFOR
    CASE 2:
      FOR i FROM 1 TO count DO
        moved := targets{i};
      ENDFOR
    CASE 3:
      FOR i FROM 1 TO 2 DO
        moved := moved + i;
      ENDFOR
    ENDTEST
    moved := moved + i;
  ERROR
    TPWrite "move failed";
    RETRY;
  ENDPROC
ENDMODULE
