! The robot task serves the PC's commands and raises a flag for the logger
! (logger.mod) after each "run"; the PC may send "home" for ever.
MODULE prog
  PERS bool moved := FALSE;
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  PROC main()
    SocketCreate server;
    SocketBind server, "127.0.0.1", 1025;
    SocketListen server;
    SocketAccept server, client;
    WHILE TRUE DO
      SocketReceive client \Str:=command;
      IF command = "run" THEN
        WaitUntil NOT moved;
        moved := TRUE;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
