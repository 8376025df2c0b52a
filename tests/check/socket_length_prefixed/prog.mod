MODULE SocketLengthPrefixed
    ! A binary server in the style of the ROS drivers: each frame is a 4-byte length, then
    ! a header unpacked into record components (msg_type, comm_type) and data copied into
    ! a rawbytes component from byte 9.  The caller checks the type and the data's length,
    ! then dispatches on a sequence number unpacked from the data.  The messages tried are
    ! frames of 12 bytes after their length (type 11, each sequence class) and a frame of
    ! length 0, whose header cannot be unpacked (uncaught ERR_OUTOFBND, as in abb_driver).
    RECORD frame_header
        num msg_type;
        num comm_type;
    ENDRECORD
    RECORD frame
        frame_header header;
        rawbytes data;
    ENDRECORD
    VAR socketdev server;
    VAR socketdev client;
    VAR frame received;
    VAR num sequence := 0;
    VAR num done := 0;

    PROC ReceiveFrame(VAR socketdev peer, VAR frame message)
        VAR rawbytes buffer;
        VAR num length;
        SocketReceive peer \RawData:=buffer \ReadNoOfBytes:=4 \Time:=WAIT_MAX;
        UnpackRawBytes buffer, 1, length \IntX:=UDINT;
        SocketReceive peer \RawData:=buffer \ReadNoOfBytes:=length \Time:=WAIT_MAX;
        UnpackRawBytes buffer, 1, message.header.msg_type \IntX:=DINT;
        UnpackRawBytes buffer, 5, message.header.comm_type \IntX:=DINT;
        CopyRawBytes buffer, 9, message.data, 1;
    ENDPROC

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 11000;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            ReceiveFrame client, received;
            IF received.header.msg_type = 11 AND RawBytesLen(received.data) >= 4 THEN
                UnpackRawBytes received.data, 1, sequence \IntX:=DINT;
                TEST sequence
                CASE -1:
                    done := 1;
                CASE -3:
                    done := 3;
                DEFAULT:
                    done := 2;
                ENDTEST
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
