MODULE Prog
  ! A server loop that never ends, with an UNDO handler that closes the sockets (the
  ! gieldid/DatawoodGH server): the handler runs when the operator moves the program
  ! pointer or resets the program, which the check does not follow.  Its lines, and the
  ! procedure only it calls, were "never reached with the socket messages tried": no
  ! message reaches them, and they are not dead either.  One warning says what it rests on.
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR num served := 0;
  PROC main()
    SocketCreate server;
    SocketBind server, "0.0.0.0", 1025;
    SocketListen server;
    SocketAccept server, client \Time:=WAIT_MAX;
    WHILE TRUE DO
      SocketReceive client \Str:=command \Time:=WAIT_MAX;
      IF command = "stop" THEN
        served := 0;
      ELSE
        served := 1;
      ENDIF
    ENDWHILE
  UNDO
    SocketClose client;
    CloseServer;
  ENDPROC
  PROC CloseServer()
    SocketClose server;
  ENDPROC
ENDMODULE
