MODULE JointMessage
    ! A message of a sequence number and 10 joints, 4 bytes each: 7 joints are packed, the
    ! 8th left as a gap, the 9th and 10th packed past it (as ABB YuMi's ROS driver does).
    ! Packing past the bytes held is no error: the gap reads as zeros and the length grows.
    VAR rawbytes message;
    VAR num value;
    VAR num i;

    PROC main()
        ClearRawBytes message;
        PackRawBytes 1, message, 1 \IntX:=DINT;
        FOR joint FROM 1 TO 7 DO
            PackRawBytes joint, message, 1 + joint * 4 \Float4;
        ENDFOR
        FOR i FROM 1 TO 2 DO
            PackRawBytes 0, message, 33 + i * 4 \Float4;
        ENDFOR
        IF RawBytesLen(message) <> 44 THEN
            value := 1 / 0;
        ENDIF
        UnpackRawBytes message, 33, value \Float4;
        IF value <> 0 THEN
            value := 1 / 0;
        ENDIF
    ENDPROC
ENDMODULE
