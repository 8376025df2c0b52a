! Task 1: a server socket set up and closed in a loop (the machine writes the socket's
! states), listening too early while the other task's phase is 1 (ERR_SOCK_CLOSED: the
! machine's guard fails and Python raises), a client that connects and sends, then a
! timed wait on the phase.
MODULE Sockets
  VAR socketdev server;
  VAR socketdev client;
  VAR bool late := FALSE;
  PERS num phase := 0;
  PROC main()
    WHILE TRUE DO
      SocketCreate server;
      IF phase = 1 AND late THEN
        SocketListen server;
      ENDIF
      SocketBind server, "127.0.0.1", 1025;
      SocketListen server;
      SocketClose server;
      SocketCreate client;
      SocketConnect client, "127.0.0.1", 1026;
      SocketSend client \Str:="ready";
      SocketClose client;
      WaitUntil phase <> 2 \MaxTime:=5 \TimeFlag:=late;
    ENDWHILE
  ENDPROC
ENDMODULE
