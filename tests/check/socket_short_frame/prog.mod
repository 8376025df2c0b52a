MODULE SocketShortFrame
    ! The ROS drivers' integrity check: a frame of the expected type whose data is shorter
    ! than the code needs (RawBytesLen(data) < 4) is reported and raised.  Besides the frames
    ! that tell the types and sequence numbers apart, the messages hold the first frame cut
    ! one byte short of the length compared (type 11, 3 bytes of data).
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
            IF received.header.msg_type = 11 THEN
                IF RawBytesLen(received.data) < 4 THEN
                    done := 4;             ! (ROS: "Insufficient data", RAISE ERR_OUTOFBND)
                    RAISE ERR_OUTOFBND;
                ENDIF
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
