MODULE SocketReadCount
    ! Written for the test (issue 28): the length of each message is the first 8 bytes the
    ! client sends, and the whole message is then read with \ReadNoOfBytes:=length+8.  A
    ! rawbytes holds at most 1,024 bytes, so a length the header makes larger fails.
    VAR socketdev server;
    VAR socketdev client;
    VAR rawbytes buffer;
    VAR num msg_length := 0;
    VAR num bytes_rcvd := 0;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 11000;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \RawData:=buffer \ReadNoOfBytes:=8 \Time:=WAIT_MAX;
            UnpackRawBytes buffer, 1, msg_length \IntX:=ULINT;
            SocketReceive client \RawData:=buffer \ReadNoOfBytes:=(msg_length + 8)
                \NoRecBytes:=bytes_rcvd \Time:=WAIT_MAX;
            IF msg_length > 4 THEN
                TPWrite "long message";
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
