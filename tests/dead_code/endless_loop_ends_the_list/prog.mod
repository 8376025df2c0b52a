MODULE Prog
  ! A server loop WHILE TRUE that no GOTO leaves (RAPID's EXIT ends the program, it does
  ! not leave the loop: MojitoShader's RoboReadV2): the statements after it never run,
  ! whatever a client sends, so they are "never reached under any input" although other
  ! unreached code rests on the messages tried.  In Drain a GOTO may leave its loop: the
  ! code after it waits for the messages.
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR num served := 0;
  PROC main()
    SocketCreate server;
    SocketBind server, "0.0.0.0", 1025;
    SocketListen server;
    SocketAccept server, client \Time:=WAIT_MAX;
    Drain;
    WHILE TRUE DO
      SocketReceive client \Str:=command \Time:=WAIT_MAX;
      IF command = "CLOSE" THEN
        EXIT;
      ENDIF
      served := served + 1;
    ENDWHILE
    SocketClose client;
    served := 0;
  ENDPROC
  PROC Drain()
    WHILE TRUE DO
      SocketReceive client \Str:=command \Time:=WAIT_MAX;
      IF StrLen(command) > 40 GOTO done;
      IF command = "GO" RETURN;
    ENDWHILE
  done:
    served := -1;
  ENDPROC
ENDMODULE
