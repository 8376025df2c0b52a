MODULE Prog
  ! An arm no message tried opens, whose last statement follows ExitCycle (the Hanoi socket
  ! copies' RETRY after ExitCycle).  The statement after the jump is dead whatever a
  ! client sends; the rest of the arm rests on the messages tried.  They were one stretch
  ! worded with the messages; they are now two warnings, each with its own wording.
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR num value := 0;
  VAR num served := 0;
  PROC main()
    SocketCreate server;
    SocketBind server, "0.0.0.0", 1025;
    SocketListen server;
    SocketAccept server, client \Time:=WAIT_MAX;
    WHILE TRUE DO
      SocketReceive client \Str:=command \Time:=WAIT_MAX;
      IF StrToVal(command, value) THEN
        IF value * 3 = 7 THEN
          served := 0;
          ExitCycle;
          served := 5;
        ENDIF
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
