MODULE Prog
  ! A procedure whose every call is dead code (after the endless server loop, or in a
  ! procedure only such code calls) never runs whatever a client sends: dtcameron's
  ! CloseConnection, called once after WHILE TRUE. Its warning says "under any input", as
  ! the statements after the loop do.  Report is also called where a number a client may
  ! send leads (7/3: no message tried parses to it): its warning keeps resting on the
  ! messages tried.
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR num served := 0;
  VAR num value := 0;
  PROC main()
    SocketCreate server;
    SocketBind server, "0.0.0.0", 1025;
    SocketListen server;
    SocketAccept server, client \Time:=WAIT_MAX;
    WHILE TRUE DO
      SocketReceive client \Str:=command \Time:=WAIT_MAX;
      IF StrToVal(command, value) THEN
        IF value * 3 = 7 Report;
      ENDIF
      served := served + 1;
    ENDWHILE
    CloseConnection;
    Report;
  ENDPROC
  PROC CloseConnection()
    SocketClose client;
    Forget;
  ENDPROC
  PROC Forget()
    served := 0;
  ENDPROC
  PROC Report()
    served := -1;
  ENDPROC
ENDMODULE
