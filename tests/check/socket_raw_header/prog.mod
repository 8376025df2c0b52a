MODULE SocketRawHeader
    VAR socketdev server;
    VAR socketdev client;
    VAR rawbytes buffer;
    VAR num msg_type := 0;
    VAR num handled := 0;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 11000;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \RawData:=buffer \ReadNoOfBytes:=4 \Time:=WAIT_MAX;
            UnpackRawBytes buffer, 1, msg_type \IntX:=DINT;
            IF msg_type = 10 THEN
                handled := 1;
            ELSEIF msg_type = 11 THEN
                handled := 2;
            ELSEIF msg_type > 100 THEN
                handled := 3;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
