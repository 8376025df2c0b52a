MODULE MainModule
  ! Tests: a message queue without partners times out (ERR_RMQ_TIMEOUT), and in run the
  ! camera finds no part (CamNumberOfResults 0, CamGetResult raises ERR_CAM_NO_MORE_DATA).
  VAR rmqslot rsPlc;
  VAR rmqmessage rmMsg;
  VAR cameradev camTop;
  VAR cameratarget ctPart;
  PROC main()
    RMQFindSlot rsPlc, "RMQ_PLC";
    RMQSendMessage rsPlc, "ready";
    WaitForAnswer;
    CamSetProgramMode camTop;
    CamLoadJob camTop, "parts.job";
    CamSetRunMode camTop;
    CamReqImage camTop;
    TPWrite "parts: " \Num:=CamNumberOfResults(camTop);
    CamGetResult camTop, ctPart;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_CAM_NO_MORE_DATA TPWrite "no part in the image";
    RETURN;
  ENDPROC
  PROC WaitForAnswer()
    RMQReadWait rmMsg \TimeOut:=5;
  ERROR
    IF ERRNO = ERR_RMQ_TIMEOUT TPWrite "PLC did not answer";
    RETURN;
  ENDPROC
ENDMODULE
