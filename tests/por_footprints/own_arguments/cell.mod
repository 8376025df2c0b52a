MODULE Cell
  ! Predefined procedures that touch only their arguments (sockets, rawbytes) or nothing
  ! (no effect) are local when what they write is the task's own and what they read no
  ! other task writes.
  VAR socketdev server;
  VAR socketdev client;
  VAR rawbytes buffer;
  VAR string reply := "";
  VAR num length := 0;
  PERS string shared := "";
  PERS num speed := 100;
  PROC main()
    SocketCreate server;                           ! LOCAL
    SocketBind server, "127.0.0.1", 1025;          ! LOCAL
    SocketListen server;                           ! LOCAL
    Serve server, client;                          ! LOCAL
    IF SocketGetStatus(client) = SOCKET_CONNECTED THEN  ! LOCAL
      SocketReceive client \RawData:=buffer \Time:=5;  ! LOCAL
      UnpackRawBytes buffer, 1, length \IntX:=UDINT;   ! VISIBLE
      SocketSend client \Str:=shared;              ! SHARED
      SocketSend client \Str:=reply;               ! LOCAL
    ENDIF
    AccSet 50, 50;                                 ! LOCAL
    ErrWrite \W, "cell", "served";                 ! LOCAL
    VelSet speed, 1000;                            ! SHARED
    SocketClose client;                            ! LOCAL
  ENDPROC
  PROC Serve(VAR socketdev listener, VAR socketdev connection \num wait)
    VAR num limit := 10;
    IF Present(wait) limit := wait;                ! LOCAL
    SocketAccept listener, connection \Time:=limit;  ! LOCAL
  ENDPROC
ENDMODULE
